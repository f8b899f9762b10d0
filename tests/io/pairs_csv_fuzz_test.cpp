// The pair reader on mutated input: every outcome is a parsed file or an InputError naming a
// line; nothing else escapes. Run under the sanitizer build (scripts/sanitize.sh) too.

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <random>

#include "mtcs/io/input_error.h"
#include "mtcs/io/pairs_csv.h"
#include "fuzz_mutate.h"
#include "support/scratch_file.h"

TEST_CASE("pairs CSV reader survives mutated input", "[cli][fuzz]") {
  const std::string seed =
      "id,p0x,p0y,p0z,p1x,p1y,p1z,r0,q0x,q0y,q0z,q1x,q1y,q1z,r1,dist_lo,dist_hi,category\n"
      "a,0,0,0,10,0,0,1,0,5,0,10,5,0,2,2,2,exact\n"
      "b,1e6,1e6,1e6,1e6,1e6,1e6,0.5,-3,4,5,6,7,8,0.25,,,x\n";
  const std::string alphabet = "0123456789,.-+eE\n\r\t xnaif#";
  std::mt19937_64 rng(99);
  const auto path = mtcs_test::scratch_dir("fuzz_pairs") / "input.csv";
  int parsed = 0, rejected = 0;
  for (int i = 0; i < 3000; ++i) {
    const std::string s = mtcs_test::mutate(seed, alphabet, rng, 6, 8);
    std::ofstream(path, std::ios::binary) << s;
    try {
      const auto pairs = mtcs::io::read_pairs_csv(path.string());
      for (const auto& p : pairs) REQUIRE(std::isfinite(p.a.radius));
      ++parsed;
    } catch (const mtcs::io::InputError& e) {
      REQUIRE(e.line() >= 1);
      ++rejected;
    }
  }
  CHECK(parsed > 0);
  CHECK(rejected > 0);
}
