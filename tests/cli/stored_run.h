#pragma once
// What a run left in its store, read back for CLI tests that compare runs (resume, threads,
// interruption): every stored generation flattened, and how many generations are stored.

#include <filesystem>
#include <vector>

#include "mtcs/store/run_store.h"

namespace mtcs_test {

// Every stored row, flattened in order: per generation its summary (not the wall time; with the
// ES's stall count) and each member's genome, step sizes and objectives, as exact doubles.
inline std::vector<std::vector<double>> stored_rows(const std::filesystem::path& dir) {
  const auto db = mtcs::store::RunStore::open((dir / "run.sqlite").string());
  std::vector<std::vector<double>> out;
  for (const auto& s : db.summaries()) {
    const auto g = db.generation(s.index);
    out.push_back({double(s.index), double(s.evaluations), s.best, s.feasible_share, double(g->stalled)});
    for (const auto& ind : g->population) {
      out.push_back(ind.x);
      out.push_back(ind.steps);
      out.push_back(ind.score.objectives);
    }
  }
  return out;
}

// Generations stored so far; 0 while the store does not exist or is not readable yet.
inline std::size_t stored_generations(const std::filesystem::path& dir) {
  try {
    return mtcs::store::RunStore::open((dir / "run.sqlite").string()).summaries().size();
  } catch (const std::exception&) {
    return 0;
  }
}

}  // namespace mtcs_test
