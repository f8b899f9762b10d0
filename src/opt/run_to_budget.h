#pragma once
// The loop every optimiser of opt shares: from a stored generation (resume) or a fresh initial
// one, step until the budget is spent, reporting each generation (storage, progress).

#include <functional>

#include "mtcs/opt/evolution_strategy.h"

namespace mtcs::opt {

template <class Algorithm>
Generation run_to_budget(const Algorithm& algorithm, const Generation* start,
                         const std::function<void(const Generation&)>& on_generation) {
  Generation g = start ? *start : algorithm.initial();
  if (!start && on_generation) on_generation(g);
  while (!algorithm.done(g)) {
    g = algorithm.step(g);
    if (on_generation) on_generation(g);
  }
  return g;
}

}  // namespace mtcs::opt
