// Logs and progress on stderr through spdlog: --quiet leaves them out (the results are written
// all the same), --verbose adds the resolved run config, and the two exclude each other.

#include <catch2/catch.hpp>

#include "run_mtcs.h"
#include "support/paths.h"

using mtcs_test::run_mtcs_err;
namespace fs = std::filesystem;

TEST_CASE("mtcs optimize and replay: --quiet, default and --verbose logs", "[cli][log]") {
  const std::string mold = MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml";  // fast: wall distances
  const fs::path dir = mtcs_test::scratch("log_flags", "runs");
  fs::remove_all(dir);
  const auto out = [&](const std::string& name) { return " --evaluations 200 --out " + (dir / name).string(); };

  auto r = run_mtcs_err("log_flags", "optimize " + mold + out("quiet") + " --quiet");
  CHECK(r.code == 0);
  CHECK(r.err.empty());
  CHECK(fs::exists(dir / "quiet" / "summary.json"));

  r = run_mtcs_err("log_flags", "optimize " + mold + out("plain"));
  CHECK(r.code == 0);
  CHECK(r.err.find("best layout:") != std::string::npos);
  CHECK(r.err.find("run config:") == std::string::npos);

  r = run_mtcs_err("log_flags", "optimize " + mold + out("verbose") + " --verbose");
  CHECK(r.code == 0);
  CHECK(r.err.find("run config:\nalgorithm: es\n") != std::string::npos);
  CHECK(r.err.find("evaluations: 200\n") != std::string::npos);

  r = run_mtcs_err("log_flags", "replay " + (dir / "quiet").string() + " --no-plots --quiet");
  CHECK(r.code == 0);
  CHECK(r.err.empty());
  r = run_mtcs_err("log_flags", "replay " + (dir / "quiet").string() + " --no-plots");
  CHECK(r.err.find("0 objective mismatch(es)") != std::string::npos);

  CHECK(run_mtcs_err("log_flags", "optimize " + mold + out("both") + " --quiet --verbose").code == 2);
  fs::remove_all(dir);
}
