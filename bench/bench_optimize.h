#pragma once
// Optimiser comparisons on a mold at equal budgets (mtcs bench optimize; experiments/optimize).

#include <string>
#include <vector>

namespace mtcs::bench {

// mtcs bench optimize: each of `algorithms` (bench/mold_peers.h: es, sms-emoa, random, isres,
// crs2, cmaes, nsga2, moead; nlopt: isres under its old name) on the mold over seeds 1..seeds;
// CSV on stdout, the anytime course in `trace` when given. The fixed-topology peers keep the
// topology of the layout file `topology`, by default each seed's first random sample.
// Hypervolumes: of the feasible non-dominated layouts evaluated, in scaled objectives, against
// one reference point for every run (the config's ref, or the run's default for the config's
// seed), printed on stderr.
struct OptimizeRuns {
  std::string mold, config, topology, trace;
  std::string layouts;  // folder for each run's best layout (ALGORITHM-seedS.layout.yaml); empty: none
  std::vector<std::string> algorithms{"es"};
  int seeds = 11;
  long evaluations = 20000;
  long trace_every = 0;  // evaluations between anytime points; 0: a hundredth of the budget
};
int bench_optimize(const OptimizeRuns& runs);

}  // namespace mtcs::bench
