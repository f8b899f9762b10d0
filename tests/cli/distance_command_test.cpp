// mtcs distance end to end: the binary on good and malformed input (exit code 2, a message with
// file, line, column and field, and no output file).

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <string>

#include "run_mtcs.h"

namespace fs = std::filesystem;

namespace {

using mtcs_test::Run;

fs::path scratch(const std::string& name) { return mtcs_test::scratch("distance_cli", name); }
Run run_mtcs(const std::string& args) { return mtcs_test::run_mtcs_err("distance_cli", args); }

fs::path write_file(const std::string& name, const std::string& text) {
  const fs::path p = scratch(name);
  std::ofstream(p) << text;
  return p;
}

const char* kHeader = "id,p0x,p0y,p0z,p1x,p1y,p1z,r0,q0x,q0y,q0z,q1x,q1y,q1z,r1\n";

}  // namespace

TEST_CASE("mtcs distance writes id,distance,feature,bounded", "[cli]") {
  const auto in = write_file("mtcs_ok.csv", std::string(kHeader) +
                                                "a,0,0,0,10,0,0,1,0,5,0,10,5,0,2\n"
                                                "b,0,0,0,10,0,0,1,20,50,0,30,50,0,2\n");
  const auto out = scratch("mtcs_ok_out.csv");
  fs::remove(out);
  const Run r = run_mtcs("distance --pairs " + in.string() + " --out " + out.string() + " --upper-bound 5");
  REQUIRE(r.code == 0);
  std::ifstream f(out);
  std::string header, row1, row2;
  std::getline(f, header), std::getline(f, row1), std::getline(f, row2);
  CHECK(header == "id,distance,feature,bounded");
  CHECK(row1 == "a,2,shell-shell,0");
  CHECK(row2.rfind("b,", 0) == 0);
  CHECK(row2.substr(row2.size() - 2) == ",1");  // the axes are 50 apart, far beyond U = 5: bounded
}

TEST_CASE("mtcs distance rejects a malformed row with its line and column", "[cli]") {
  const auto in = write_file("mtcs_bad.csv", std::string(kHeader) +
                                                 "a,0,0,0,10,0,0,1,0,5,0,10,5,0,2\n"
                                                 "b,0,0,0,10,0,zero,1,0,5,0,10,5,0,2\n");
  const auto out = scratch("mtcs_bad_out.csv");
  fs::remove(out);
  const Run r = run_mtcs("distance --pairs " + in.string() + " --out " + out.string());
  CHECK(r.code == 2);
  CHECK(r.err.find(in.string() + ":3:14:") != std::string::npos);
  CHECK(r.err.find("'p1z'") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("mtcs distance rejects a missing column, a short row and a negative radius", "[cli]") {
  const auto out = scratch("mtcs_bad2_out.csv");
  fs::remove(out);
  const auto no_r1 = write_file("mtcs_nor1.csv", "id,p0x,p0y,p0z,p1x,p1y,p1z,r0,q0x,q0y,q0z,q1x,q1y,q1z\n");
  Run r = run_mtcs("distance --pairs " + no_r1.string() + " --out " + out.string());
  CHECK(r.code == 2);
  CHECK(r.err.find("'r1'") != std::string::npos);
  const auto short_row = write_file("mtcs_short.csv", std::string(kHeader) + "a,0,0,0,10,0,0,1,0,5\n");
  r = run_mtcs("distance --pairs " + short_row.string() + " --out " + out.string());
  CHECK(r.code == 2);
  CHECK(r.err.find(":2:") != std::string::npos);
  const auto negative = write_file("mtcs_neg.csv", std::string(kHeader) + "a,0,0,0,10,0,0,-1,0,5,0,10,5,0,2\n");
  r = run_mtcs("distance --pairs " + negative.string() + " --out " + out.string());
  CHECK(r.code == 2);
  CHECK(r.err.find("'r0'") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
  r = run_mtcs("distance --pairs /nonexistent.csv --out " + out.string());
  CHECK(r.code == 2);
}

// Issue 16, "Messages": "--upper-bound 0" answered with a range up to the largest double written
// out in 309 digits.
TEST_CASE("mtcs distance: --upper-bound 0 is refused with a readable message", "[cli][issue16]") {
  const auto in = write_file("mtcs_bound.csv", std::string(kHeader) + "a,0,0,0,10,0,0,1,0,5,0,10,5,0,2\n");
  for (const std::string bound : {"0", "-1", "nan", "x"}) {
    const Run r = run_mtcs("distance --pairs " + in.string() + " --out " + scratch("bound_out.csv").string() +
                           " --upper-bound " + bound);
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("--upper-bound: must be a number above 0, got " + bound));
    CHECK(r.err.size() < 200);
  }
}
