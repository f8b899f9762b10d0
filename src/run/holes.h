#pragma once
// Holes of an axis-parallel circuit as the run module moves them: along axis k, a run of
// consecutive waypoints that share the coordinate (the ends of a hole across k) is one
// variable, so that a move keeps aligned holes aligned. The mutation and the polish both use it.

#include <cmath>
#include <cstddef>
#include <utility>
#include <vector>

#include "mtcs/geometry/primitives.h"

namespace mtcs::run {

// [first, last) index ranges covering w, one per run of equal coordinate k (relative 1e-9).
// Calls f(first, last) for each run in order, allocating nothing (the mutation's hot loop). f may
// change its own run's coordinates: the next run is read afterwards, from its own points only.
template <class F>
void for_each_aligned_run(const std::vector<geometry::Vec3>& w, int k, F&& f) {
  std::size_t i = 0;
  while (i < w.size()) {
    std::size_t j = i + 1;
    while (j < w.size() && std::abs(w[j][k] - w[i][k]) <= 1e-9 * (1 + std::abs(w[i][k]))) ++j;
    f(i, j);
    i = j;
  }
}

inline std::vector<std::pair<std::size_t, std::size_t>> aligned_runs(const std::vector<geometry::Vec3>& w, int k) {
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  for_each_aligned_run(w, k, [&](std::size_t first, std::size_t last) { runs.emplace_back(first, last); });
  return runs;
}

}  // namespace mtcs::run
