// The benchmarks and their peers live in mtcs-bench: the mtcs binary links none of FCL, pagmo or
// CGAL's intersection oracle, and `mtcs bench` hands its arguments and exit code through.

#include <catch2/catch.hpp>

#include <cstdio>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "cli/run_mtcs.h"
#include "support/paths.h"

using namespace mtcs_test;

namespace {

// Lines of `nm -C BINARY` that contain `needle`, counted (-1 when nm cannot run).
int symbols_with(const std::string& needle) {
  const std::string cmd = "nm -C " + std::string(MTCS_BINARY) + " 2>/dev/null";
  FILE* pipe = ::popen(cmd.c_str(), "r");
  if (!pipe) return -1;
  int total = 0, hits = 0;
  char line[4096];
  while (std::fgets(line, sizeof line, pipe)) {
    ++total;
    if (std::string(line).find(needle) != std::string::npos) ++hits;
  }
  ::pclose(pipe);
  return total > 0 ? hits : -1;
}

}  // namespace

TEST_CASE("mtcs binary: no FCL, pagmo or CGAL-oracle symbols", "[cli][bench]") {
  // The mold's own symbols are there: nm did read a symbol table.
  REQUIRE(symbols_with("mtcs::eval::Pipeline") > 0);
  CHECK(symbols_with("fcl::") == 0);
  CHECK(symbols_with("pagmo::") == 0);
  CHECK(symbols_with("Polygon_mesh_processing") == 0);
  CHECK(symbols_with("mtcs::bench::") == 0);
}

TEST_CASE("mtcs bench: runs mtcs-bench with the arguments and its exit code", "[cli][bench]") {
  const fs::path out = scratch("bench_program", "sms.csv");
  REQUIRE(run_mtcs("bench sms-emoa --problem zdt1 --seeds 1 --evaluations 300 --algorithms sms-emoa,nsga2 > " +
                   out.string()) == 0);
  const std::string csv = read_text(out);
  CHECK(csv.find("problem,algorithm,seed,evaluations,hypervolume,seconds,cpu_seconds\n") == 0);
  CHECK(csv.find("zdt1,nsga2,1,300,") != std::string::npos);  // pagmo's NSGA-II ran: the peer is in mtcs-bench
  // A bad subcommand is mtcs-bench's usage error: exit 2, as before the split.
  CHECK(run_mtcs("bench no-such-benchmark") == 2);
  // Without mtcs-bench beside it, mtcs says so.
  const fs::path alone = scratch("bench_program", "mtcs");
  fs::copy_file(MTCS_BINARY, alone, fs::copy_options::overwrite_existing);
  const fs::path err = scratch("bench_program", "alone.err");
  const int code = WEXITSTATUS(std::system((alone.string() + " bench distance 2>" + err.string()).c_str()));
  CHECK(code == 127);
  CHECK(read_text(err).find("mtcs-bench") != std::string::npos);
  // ... and how to get it on a machine the demo set up (scripts/setup.sh --minimal has no peers).
  CHECK(read_text(err).find("scripts/setup.sh") != std::string::npos);
  CHECK(read_text(err).find("-DMTCS_BUILD_BENCH=ON") != std::string::npos);
}

TEST_CASE("mtcs bench part: each command cold and warm for mtcs and a peer binary, then the rates", "[cli][bench]") {
  // The peer: this mtcs under another name (its rows must carry that name, its commands run).
  const fs::path peer = scratch("bench_part", "mtcs-peer");
  fs::remove(peer);
  fs::create_symlink(MTCS_BINARY, peer);
  const fs::path out = scratch("bench_part", "part.csv");
  REQUIRE(run_mtcs("bench part " + std::string(MTCS_SOURCE_DIR) + "/molds/plate.yaml --children 4 --randoms 2 --peer " +
                   peer.string() + " > " + out.string() + " 2>/dev/null") == 0);
  std::istringstream csv(read_text(out));
  std::string line;
  std::getline(csv, line);
  CHECK(line == "mold,program,measure,value,unit");
  std::map<std::string, int> rows;  // program's kind, measure
  while (std::getline(csv, line)) {
    std::vector<std::string> f;
    std::istringstream fields(line);
    for (std::string s; std::getline(fields, s, ',');) f.push_back(s);
    REQUIRE(f.size() == 5);
    INFO(line);
    CHECK(std::stod(f[3]) > 0);
    ++rows[(f[1] == peer.string() ? "peer " : "mtcs ") + f[2]];
  }
  for (const std::string program : {"mtcs ", "peer "})
    for (const std::string command : {"evaluate_", "thermal_"})
      for (const std::string when : {"cold", "warm"}) {
        CHECK(rows[program + command + when] == 1);
        CHECK(rows[program + command + when + "_peak"] == 1);
      }
  for (const std::string in_process : {"first_layout", "child", "random", "in_process_peak"}) {
    CHECK(rows["mtcs " + in_process] == 1);
    CHECK(rows["peer " + in_process] == 0);
  }
  // A peer that fails is an error, not a row, and the benchmark's scratch folder goes with it.
  const fs::path tmp = scratch("bench_part", "tmp");
  fs::remove_all(tmp);
  fs::create_directories(tmp);
  CHECK(run_mtcs("bench part " + std::string(MTCS_SOURCE_DIR) + "/molds/plate.yaml --peer /bin/false", "/dev/null",
                 "TMPDIR=" + tmp.string()) != 0);
  CHECK(fs::is_empty(tmp));
}
