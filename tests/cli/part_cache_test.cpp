// mtcs keeps a part's panel matrix (and its potentials at the panels) between commands
// (mtcs/io/disk_cache.h): a second run reads them and scores the layout as the first did, bit for bit; the kept matrix is what that run uses
// (a valid file holding another matrix changes the score); a damaged file is rebuilt as it was;
// --no-cache reads and keeps nothing.

#include <catch2/catch.hpp>

#include <cstring>
#include <nlohmann/json.hpp>

#include "run_mtcs.h"
#define XXH_INLINE_ALL
#include <xxhash.h>

using namespace mtcs_test;

namespace {

const std::string kMold = std::string(MTCS_SOURCE_DIR) + "/molds/l_bracket.yaml";
const std::string kLayout = std::string(MTCS_SOURCE_DIR) + "/molds/l_bracket.layout.yaml";

// mtcs evaluate --json of the bundled L-bracket with its cache in `cache`: objectives and score.
nlohmann::json evaluate(const fs::path& cache, const std::string& extra = "") {
  const fs::path out = scratch("part_cache", "out.json");
  const std::string command = "MTCS_CACHE_DIR=" + cache.string() + " " + MTCS_BINARY + " evaluate " + kMold +
                              " --layout " + kLayout + " --json " + extra + " >" + out.string() + " 2>/dev/null";
  REQUIRE(WEXITSTATUS(std::system(command.c_str())) == 0);
  const auto j = nlohmann::json::parse(read_text(out));
  return {{"objectives", j["objectives"]}, {"scalarised", j["scalarised"]}};
}

std::vector<fs::path> files_in(const fs::path& dir) {
  std::vector<fs::path> files;
  if (fs::exists(dir))
    for (const auto& e : fs::directory_iterator(dir)) files.push_back(e.path());
  return files;
}

std::string bytes_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

void write_bytes(const fs::path& p, const std::string& bytes) { std::ofstream(p, std::ios::binary) << bytes; }

}  // namespace

TEST_CASE("mtcs evaluate keeps the part's panel matrix between runs", "[cli][cache]") {
  const fs::path cache = scratch("part_cache", "cache");
  const nlohmann::json first = evaluate(cache);
  // The panel matrix, and the panels' potentials at their own points (the film's part of the
  // matrix; the potentials at the samples are kept in memory only).
  std::vector<fs::path> kept, potentials;
  for (const fs::path& f : files_in(cache))
    (f.filename().string().rfind("panel-matrix-", 0) == 0 ? kept : potentials).push_back(f);
  REQUIRE(kept.size() == 1);
  REQUIRE(potentials.size() == 1);
  CHECK(potentials[0].filename().string().rfind("void-potentials-", 0) == 0);
  CHECK(fs::file_size(potentials[0]) == 48 + 8 * 378 * 378);
  const std::string original = bytes_of(kept[0]);
  // The L-bracket's 378 panels: 378^2 doubles after a 48-byte header.
  CHECK(original.size() == 48 + 8 * 378 * 378);

  CHECK(evaluate(cache) == first);  // read back: the same score, to the last bit

  // A valid file with another matrix (every entry 10 % larger but the diagonal's 1/2, its
  // checksum made good): the run uses what is kept. Likewise the potentials.
  const auto scaled = [](const std::string& bytes) {
    std::string changed = bytes;
    const std::size_t n = (changed.size() - 48) / 8;
    for (std::size_t k = 0; k < n; ++k) {
      double v;
      std::memcpy(&v, changed.data() + 48 + 8 * k, 8);
      v = v == 0.5 ? v : 1.1 * v;
      std::memcpy(changed.data() + 48 + 8 * k, &v, 8);
    }
    const std::uint64_t checksum = XXH3_64bits(changed.data() + 48, changed.size() - 48);
    std::memcpy(changed.data() + 40, &checksum, 8);
    return changed;
  };
  write_bytes(kept[0], scaled(original));
  CHECK(evaluate(cache) != first);
  const std::string potentials_bytes = bytes_of(potentials[0]);
  write_bytes(kept[0], original);
  write_bytes(potentials[0], scaled(potentials_bytes));
  CHECK(evaluate(cache) != first);
  write_bytes(potentials[0], potentials_bytes);

  // A damaged file (one flipped bit, the checksum as it was): built again, the same as the first.
  for (const auto& [file, bytes] : {std::pair(kept[0], original), std::pair(potentials[0], potentials_bytes)}) {
    std::string changed = bytes;
    changed[48 + 8 * 1000] ^= 4;
    write_bytes(file, changed);
    CHECK(evaluate(cache) == first);
    CHECK(bytes_of(file) == bytes);
  }

  // --no-cache: the same score, nothing kept.
  const fs::path none = scratch("part_cache", "none");
  CHECK(evaluate(none, "--no-cache") == first);
  CHECK(files_in(none).empty());
}
