// mtcs bench optimize's algorithms on a mold (bench/mold_peers.h): each spends its budget and no
// more, its anytime course only improves (best objective down, hypervolume up), its best
// layout scores as its best, and a seed repeats its run.

#include <catch2/catch.hpp>

#include "bench/mold_peers.h"
#include "mtcs/run/session.h"
#include "support/paths.h"

using namespace mtcs;

TEST_CASE("mold peers: budgets, monotone anytime courses, determinism", "[opt][bench][peers]") {
  const run::Session session(MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml", {});
  run::RunConfig config = session.config();
  config.algorithm = "sms-emoa";
  config.es.mu = 10;
  config.es.lambda = 20;
  config.ref = run::scaled_reference(config, session.problem(), session.spec().objectives);
  const run::MoldOptimizer scaler(session.problem(), session.scene(), config);
  opt::Rng rng = opt::Rng::for_individual(3, 0, 0);
  const mold::Genome topology = session.problem().genome(session.problem().sample(rng));
  const long budget = 600;
  for (const auto& algorithm : bench::kMoldAlgorithms) {
    INFO(algorithm);
    const bench::PeerSetup setup{session.problem(), session.scene(), config, scaler, topology, budget, 3, 50};
    const bench::PeerResult r = bench::run_mold_algorithm(algorithm, setup);
    CHECK(r.evaluations <= budget);
    CHECK(r.evaluations >= budget / 2);
    REQUIRE(r.trace.size() >= 2);
    CHECK(r.trace.back().evaluations == r.evaluations);
    for (std::size_t k = 1; k < r.trace.size(); ++k) {
      CHECK(r.trace[k].best_feasible <= r.trace[k - 1].best_feasible);
      CHECK(r.trace[k].hypervolume >= r.trace[k - 1].hypervolume);
    }
    CHECK(r.hypervolume == r.trace.back().hypervolume);
    if (r.best.feasible) CHECK(r.best.value == r.trace.back().best_feasible);
    // The best layout kept with it (what --layouts writes) scores as the best.
    const opt::Score rescored = session.problem().evaluate(r.best_x);
    CHECK(rescored.value == r.best.value);
    CHECK(rescored.feasible == r.best.feasible);
    if (algorithm == "nsga2" || algorithm == "isres" || algorithm == "sms-emoa") {
      const bench::PeerResult again = bench::run_mold_algorithm(algorithm, setup);
      CHECK(again.best.value == r.best.value);
      CHECK(again.hypervolume == r.hypervolume);
    }
  }
}
