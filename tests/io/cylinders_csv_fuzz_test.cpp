// The cylinders reader (mtcs clearance's input) on mutated input: every outcome is a parsed file
// or an InputError naming a line; nothing else escapes. Run under the sanitizer build too.

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <unistd.h>

#include "mtcs/io/cylinders_csv.h"
#include "mtcs/io/input_error.h"
#include "fuzz_mutate.h"
#include "support/scratch_file.h"

TEST_CASE("cylinders CSV reader survives mutated input", "[io][fuzz]") {
  const std::string seed =
      "id,p0x,p0y,p0z,p1x,p1y,p1z,r,dist_lo,dist_hi,category\n"
      "near-001,0,0,0,10,0,0,1,2,2,near\n"
      "b,1e6,-1e6,1e6,1e6,1e6,1e6,0.5,,,buried\n";
  const std::string alphabet = "0123456789,.-+eE\n\r\t xnaif#\"";
  std::mt19937_64 rng(7);
  const auto path = mtcs_test::scratch_dir("fuzz_cylinders") / "input.csv";
  int parsed = 0, rejected = 0;
  for (int i = 0; i < 3000; ++i) {
    const std::string s = mtcs_test::mutate(seed, alphabet, rng, 6, 8);
    std::ofstream(path, std::ios::binary) << s;
    try {
      for (const auto& c : mtcs::io::read_cylinders_csv(path.string())) {
        REQUIRE(std::isfinite(c.cylinder.radius));
        REQUIRE(c.cylinder.p0.allFinite());
        REQUIRE(c.cylinder.p1.allFinite());
      }
      ++parsed;
    } catch (const mtcs::io::InputError& e) {
      REQUIRE(e.line() >= 1);
      ++rejected;
    }
  }
  std::filesystem::remove(path);
  CHECK(parsed > 0);
  CHECK(rejected > 0);
}
