// Issue 16: "molds/README.md and configs/README.md are stale". The parts a reader takes on trust:
// configs/es_default.yaml says "these are the defaults", so it must give exactly the code's
// defaults; every bundled mold and every config is described in its folder's README.

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "mtcs/run/run_config.h"
#include "support/paths.h"

using namespace mtcs;
namespace fs = std::filesystem;

namespace {

std::string read(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST_CASE("issue 16: configs/es_default.yaml gives exactly the defaults the code uses", "[run][issue16][docs]") {
  const std::vector<std::string> names{"uniformity", "worst_covered", "cost"};
  const run::RunConfig file = run::load_run_config(MTCS_SOURCE_DIR + "/configs/es_default.yaml", names);
  const run::RunConfig code;
  CHECK(file.algorithm == code.algorithm);
  CHECK(file.es.mu == code.es.mu);
  CHECK(file.es.lambda == code.es.lambda);
  CHECK(file.es.rho == code.es.rho);
  CHECK(file.es.plus == code.es.plus);
  CHECK(file.es.recombination == code.es.recombination);
  CHECK(file.es.restart_after == code.es.restart_after);
  CHECK(file.es.restart == code.es.restart);
  CHECK(file.es.restart_tolerance == code.es.restart_tolerance);
  CHECK(file.es.evaluations == code.es.evaluations);
  CHECK(file.es.seed == code.es.seed);
  CHECK(file.log_every == code.log_every);
  CHECK(file.mutation.insert == code.mutation.insert);
  CHECK(file.mutation.remove == code.mutation.remove);
  CHECK(file.mutation.snap == code.mutation.snap);
  CHECK(file.mutation.diameter == code.mutation.diameter);
  CHECK(file.mutation.circuit == code.mutation.circuit);
  CHECK(file.mutation.access_guided == code.mutation.access_guided);
  CHECK(file.mutation.moves == code.mutation.moves);
  CHECK(file.mutation.blend == code.mutation.blend);
  CHECK(file.mutation.reach == code.mutation.reach);
  CHECK(file.ref.empty());  // the reference point from the mold
  CHECK_FALSE(file.screen_tier.has_value());
}

TEST_CASE("issue 16: molds/README.md names every bundled mold, configs/README.md every config", "[run][issue16][docs]") {
  for (const auto& [folder, ext] : {std::pair{"molds", ".yaml"}, std::pair{"configs", ".yaml"}}) {
    const fs::path dir = fs::path(MTCS_SOURCE_DIR) / folder;
    const std::string readme = read(dir / "README.md");
    for (const auto& f : fs::directory_iterator(dir)) {
      const std::string name = f.path().filename().string();
      if (f.path().extension() != ext || name.find(".layout.") != std::string::npos) continue;
      INFO(folder << "/" << name);
      CHECK(readme.find(name) != std::string::npos);
    }
  }
}
