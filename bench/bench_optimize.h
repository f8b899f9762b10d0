#pragma once
// Optimiser comparisons at equal budgets (mtcs bench optimize; experiments/optimize).

#include <string>
#include <vector>

#include "mtcs/run/mold_problem.h"
#include "mtcs/mold/scene.h"
#include "mtcs/opt/evolution_strategy.h"

namespace mtcs::bench {

using run::MoldProblem;

struct OptimizeTrace {
  struct Point {
    long evaluations;
    double best_feasible;  // best feasible scalarised objective so far (inf: none yet)
  };
  std::vector<Point> points;
  opt::Score best;
  double seconds = 0;
};

// The ES, or random search with config.random_search.
OptimizeTrace bench_es(const MoldProblem& problem, opt::EsConfig config);
// NLopt's GN_ISRES (stochastic ranking: constraints handled natively) on the coordinates of a
// fixed topology; ports stay on their faces.
OptimizeTrace bench_nlopt(const MoldProblem& problem, const mold::Scene& scene, const mold::Genome& topology,
                          long evaluations, std::uint64_t seed);

// mtcs bench optimize: `algorithm` (es, random or nlopt) on the mold over seeds 1..seeds; CSV on
// stdout, the convergence in `trace` when given. nlopt keeps the topology of the layout file
// `topology`, by default each seed's first random sample.
struct OptimizeRuns {
  std::string mold, algorithm = "es", config, topology, trace;
  int seeds = 11;
  long evaluations = 20000;
};
int bench_optimize(const OptimizeRuns& runs);

}  // namespace mtcs::bench
