// mtcs clearance end to end: the binary on a bundled mesh and its certified cases, and on
// malformed input (exit code 2, file:line:col and field, no output file).

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>

#include "run_mtcs.h"
#include "support/paths.h"

namespace fs = std::filesystem;

namespace {

using mtcs_test::Run;

fs::path scratch(const std::string& name) { return mtcs_test::scratch("clearance_cli", name); }
Run run_mtcs(const std::string& args) { return mtcs_test::run_mtcs_err("clearance_cli", args); }

std::vector<std::vector<std::string>> read_rows(const fs::path& p) {
  std::ifstream in(p);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> row;
    std::stringstream s(line);
    std::string f;
    while (std::getline(s, f, ',')) row.push_back(f);
    rows.push_back(row);
  }
  return rows;
}

const std::string kMesh = MTCS_TEST_DATA + "/meshes/homer.off";
const std::string kCases = MTCS_TEST_DATA + "/mesh_clearance/homer.csv";

}  // namespace

TEST_CASE("mtcs clearance reproduces the certified cases of a mesh", "[cli][clearance]") {
  const auto out = scratch("homer_out.csv");
  fs::remove(out);
  // The certified CSV itself is valid input: its extra columns are ignored.
  const Run r = run_mtcs("clearance " + kMesh + " --cylinders " + kCases + " --out " + out.string());
  REQUIRE(r.code == 0);
  const auto got = read_rows(out), cases = read_rows(kCases);
  REQUIRE(got.size() == cases.size());
  CHECK(got[0] == std::vector<std::string>{"id", "distance", "bounded"});
  // homer: bbox diagonal 1.19382, lengths <= 2 x extent: S <= 2; 1e-9 S.
  for (std::size_t i = 1; i < got.size(); ++i) {
    INFO(cases[i][0]);
    REQUIRE(got[i].size() == 3);
    CHECK(got[i][0] == cases[i][0]);
    const double d = std::stod(got[i][1]), lo = std::stod(cases[i][8]), hi = std::stod(cases[i][9]);
    CHECK(d >= lo - 2e-9);
    CHECK(d <= hi + 2e-9);
    CHECK((d == 0) == (hi == 0));
    CHECK(got[i][2] == "0");
  }
}

TEST_CASE("mtcs clearance with an upper bound reports far cylinders as bounded", "[cli][clearance]") {
  const auto out = scratch("bounded_out.csv");
  fs::remove(out);
  const Run r = run_mtcs("clearance " + kMesh + " --cylinders " + kCases + " --out " + out.string() + " --upper-bound 0.01");
  REQUIRE(r.code == 0);
  const auto got = read_rows(out), cases = read_rows(kCases);
  REQUIRE(got.size() == cases.size());
  int bounded = 0;
  for (std::size_t i = 1; i < got.size(); ++i) {
    const double d = std::stod(got[i][1]), lo = std::stod(cases[i][8]);
    if (got[i][2] == "1") {
      ++bounded;
      CHECK(d >= 0.01);
      CHECK(lo >= 0.01 - 2e-9);
    } else {
      CHECK(lo < 0.01 + 2e-9);
    }
  }
  CHECK(bounded > 0);
}

TEST_CASE("mtcs clearance rejects malformed input with file:line:col", "[cli][clearance]") {
  const auto in = scratch("bad.csv");
  std::ofstream(in) << "id,p0x,p0y,p0z,p1x,p1y,p1z,r\n"
                       "a,0,0,0,1,0,0,0.1\n"
                       "b,0,0,0,1,zero,0,0.1\n";
  const auto out = scratch("bad_out.csv");
  fs::remove(out);
  Run r = run_mtcs("clearance " + kMesh + " --cylinders " + in.string() + " --out " + out.string());
  CHECK(r.code == 2);
  CHECK(r.err.find(in.string() + ":3:11") != std::string::npos);
  CHECK(r.err.find("p1y") != std::string::npos);
  CHECK_FALSE(fs::exists(out));

  std::ofstream(in, std::ios::trunc) << "id,p0x,p0y,p0z,p1x,p1y,p1z\n";
  r = run_mtcs("clearance " + kMesh + " --cylinders " + in.string() + " --out " + out.string());
  CHECK(r.code == 2);
  CHECK(r.err.find("'r'") != std::string::npos);

  // A mesh with a hole bounds no solid.
  const auto holed = scratch("holed.off");
  std::ofstream(holed) << "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n";
  std::ofstream(in, std::ios::trunc) << "id,p0x,p0y,p0z,p1x,p1y,p1z,r\na,0,0,0,1,0,0,0.1\n";
  r = run_mtcs("clearance " + holed.string() + " --cylinders " + in.string() + " --out " + out.string());
  CHECK(r.code == 2);
  CHECK(r.err.find("not a closed mesh") != std::string::npos);
  CHECK_FALSE(fs::exists(out));
}
