// The mold-spec and layout readers on mutated input: every outcome is a loaded spec or an
// InputError with a file and a field; nothing else escapes. Run under the sanitizer build too.

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include <unistd.h>

#include "mtcs/io/input_error.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/mold/mold_spec.h"
#include "support/scratch_file.h"
#include "support/paths.h"

using namespace mtcs;
namespace fs = std::filesystem;

namespace {

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string mutate(std::string s, std::mt19937_64& rng) {
  const std::string alphabet = "0123456789,.-+:[]{}#\n \"'Dxyz_abcnulltrue";
  const int edits = 1 + int(rng() % 4);
  for (int e = 0; e < edits && !s.empty(); ++e) {
    const std::size_t at = rng() % s.size();
    switch (rng() % 4) {
      case 0: s[at] = alphabet[rng() % alphabet.size()]; break;
      case 1: s.erase(at, 1 + rng() % 6); break;
      case 2: s.insert(at, 1, alphabet[rng() % alphabet.size()]); break;
      case 3: s.insert(at, s.substr(rng() % s.size(), 1 + rng() % 12)); break;
    }
  }
  return s;
}

}  // namespace

TEST_CASE("mold spec and layout readers survive mutated input", "[mold][fuzz]") {
  const fs::path dir = mtcs_test::scratch_dir("spec_fuzz");
  const std::string spec_text = slurp(MTCS_SOURCE_DIR + "/molds/extreme.yaml");
  const std::string layout_text = slurp(MTCS_SOURCE_DIR + "/molds/plate.layout.yaml");
  const auto plate = mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/plate.yaml");
  std::mt19937_64 rng(2026);
  int loaded = 0, rejected = 0;
  for (int i = 0; i < 600; ++i) {
    const fs::path spec = dir / "spec.yaml", layout = dir / "layout.yaml";
    std::ofstream(spec) << mutate(spec_text, rng);
    std::ofstream(layout) << mutate(layout_text, rng);
    try {
      mold::load_mold_spec(spec.string());
      ++loaded;
    } catch (const io::InputError& e) {
      REQUIRE(e.file() == spec.string());
      ++rejected;
    }
    try {
      mold::load_layout(layout.string(), plate);
      ++loaded;
    } catch (const io::InputError& e) {
      REQUIRE(e.file() == layout.string());
      ++rejected;
    }
  }
  CHECK(loaded > 0);
  CHECK(rejected > 0);
}
