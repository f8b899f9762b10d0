// mtcs hypervolume end to end: the output format (hypervolume alone on the first line, 17
// significant digits, then contributions in input order) and bad input.

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>
#include "support/scratch_file.h"
#include "support/paths.h"

namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  return mtcs_test::scratch_dir("hv_cli") / name;
}

int run(const std::string& args, std::string* out) {
  const fs::path o = scratch("out");
  const int status = std::system((std::string(MTCS_BINARY) + " " + args + " >" + o.string() + " 2>&1").c_str());
  std::ifstream in(o);
  std::stringstream ss;
  ss << in.rdbuf();
  *out = ss.str();
  return WEXITSTATUS(status);
}

}  // namespace

TEST_CASE("mtcs hypervolume prints the volume, then the contributions in input order", "[cli][hypervolume]") {
  const fs::path f = scratch("front.txt");
  std::ofstream(f) << "# ref 1 1\n0.25 0.75\n0.5 0.5\n0.75 0.25\n0.5 0.5\n";
  std::string out;
  REQUIRE(run("hypervolume " + f.string() + " --contributions", &out) == 0);
  std::istringstream lines(out);
  std::string hv;
  std::getline(lines, hv);
  CHECK(hv == "0.375");  // the staircase: 0.25 x 0.25 + 0.25 x 0.5 + 0.25 x 0.75
  std::vector<double> c;
  for (double v; lines >> v;) c.push_back(v);
  CHECK(c == std::vector<double>{0.0625, 0, 0.0625, 0});  // the duplicated middle point: 0 twice
  REQUIRE(run("hypervolume " + f.string() + " --ref 2,2", &out) == 0);
  CHECK(out == "2.875\n");
}

TEST_CASE("mtcs hypervolume rejects a malformed front with its line and column", "[cli][hypervolume]") {
  const fs::path f = scratch("bad.txt");
  std::ofstream(f) << "# ref 1 1\n0.25 0.75\n0.5 x5\n";
  std::string out;
  CHECK(run("hypervolume " + f.string(), &out) == 2);
  CHECK(out.find(f.string() + ":3:5:") != std::string::npos);
  const fs::path g = scratch("noref.txt");
  std::ofstream(g) << "0.25 0.75\n";
  CHECK(run("hypervolume " + g.string(), &out) == 2);
}
