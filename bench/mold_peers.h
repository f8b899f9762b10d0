#pragma once
// The optimisers compared on a mold at an equal evaluation budget (mtcs bench optimize
// --algorithm A [B ...]; experiments/optimize/peers_molds.md): mtcs's ES, SMS-EMOA and random
// search on the mold problem itself, and the peers on the coordinates of a fixed topology (the
// same decoder): pagmo's NSGA-II, MOEA/D and CMA-ES, NLopt's ISRES and CRS2. Every evaluation
// passes through one recorder: the best weighted objective, the feasible non-dominated points
// of all layouts evaluated, and their course against evaluations and wall time.

#include <cstdint>
#include <string>
#include <vector>

#include "mtcs/mold/genome.h"
#include "mtcs/mold/scene.h"
#include "mtcs/run/mold_problem.h"
#include "mtcs/run/mold_run.h"
#include "mtcs/run/run_config.h"

namespace mtcs::bench {

inline const std::vector<std::string> kMoldAlgorithms{"es", "sms-emoa", "random", "isres", "crs2", "cmaes", "nsga2", "moead"};

struct AnytimePoint {
  long evaluations;
  double seconds;
  double best_feasible;  // best feasible weighted objective so far (inf: none yet)
  double hypervolume;    // of the feasible non-dominated layouts so far, scaled objectives
};

struct PeerResult {
  opt::Score best;     // by the problem's order (feasible first, then the weighted objective)
  opt::Genotype best_x;  // its layout, in the mold problem's encoding
  double hypervolume;  // scaled, against the fixed reference
  long evaluations;
  double seconds;
  std::vector<AnytimePoint> trace;
};

struct PeerSetup {
  const run::MoldProblem& problem;
  const mold::Scene& scene;
  run::RunConfig config;             // ES/SMS-EMOA settings; config.ref: the fixed reference (scaled)
  const run::MoldOptimizer& scaler;  // scaled hypervolume against that reference
  mold::Genome topology;             // what the fixed-topology peers keep
  long evaluations;
  std::uint64_t seed;
  long trace_every;                  // evaluations between anytime points
};

// One run of `algorithm` (one of kMoldAlgorithms).
PeerResult run_mold_algorithm(const std::string& algorithm, const PeerSetup& setup);

}  // namespace mtcs::bench
