#pragma once
// An optimisation run kept in a run store: from the store's last generation (resume) or a fresh
// population to the budget, every ES generation stored, SMS-EMOA's every mu steps and its last.

#include <functional>

#include "mtcs/run/mold_run.h"
#include "mtcs/store/run_store.h"

namespace mtcs::run {

struct StoredRun {
  opt::Generation last;      // population best first (SMS-EMOA's too: by the problem's ranking)
  double seconds = 0;        // wall time of the whole run, earlier sessions included
  bool interrupted = false;  // stopped before the budget: resume continues it
};

// The rank of a stored generation's best member by the problem's ranking (the first of equals):
// what optimize wrote as best.layout.yaml for the last one. The ES stores its population best
// first (0); SMS-EMOA stores its own order (it draws parents by index, so sorting what is stored
// would change a resumed run), where the best can be any rank.
std::size_t best_rank(const opt::Generation& g, const opt::Problem& problem);

// on_stored sees each stored generation with the seconds and evaluations of this session. With
// `stop`, the run ends at the first stored generation after stop() turns true.
StoredRun run_stored(const MoldOptimizer& optimizer, const MoldProblem& problem, store::RunStore& db,
                     const std::function<void(const opt::Generation&, double seconds, long evaluations)>& on_stored,
                     const std::function<bool()>& stop = {});

}  // namespace mtcs::run
