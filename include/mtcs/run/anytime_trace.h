#pragma once
// A run's anytime behaviour from its stored generations: the best feasible weighted objective
// and the feasible front's hypervolume (scaled objectives, the run's reference point) against
// evaluations and against wall time - the curve optimisers are compared by. `mtcs replay`
// writes it as DIR/replay/anytime.csv (and anytime.png); the report embeds the same rows.

#include <string>
#include <vector>

#include "mtcs/opt/population.h"
#include "mtcs/run/mold_run.h"
#include "mtcs/store/run_store.h"

namespace mtcs::run {

struct AnytimeRow {
  int generation = 0;
  long evaluations = 0;
  double seconds = 0;        // wall time since the run started (as stored)
  double best_feasible = 0;  // in this generation's population; inf: none feasible
  double best_so_far = 0;    // over the generations up to this one
  double hypervolume = 0;    // of this population's feasible non-dominated points
  double hypervolume_so_far = 0;
};

class AnytimeTrace {
 public:
  explicit AnytimeTrace(const MoldOptimizer& optimizer);
  // Generations in stored order, each with its summary (for its wall time).
  void add(const opt::Generation& g, const store::GenerationSummary& summary);
  const std::vector<AnytimeRow>& rows() const { return rows_; }
  // The reference point of the hypervolumes, scaled: the run's (MoldOptimizer::scaled_reference),
  // or for the ES the rule's on the first generation added.
  const std::vector<double>& reference() const { return reference_; }
  void write_csv(const std::string& path) const;

 private:
  const MoldOptimizer& optimizer_;
  std::vector<double> reference_;
  std::vector<AnytimeRow> rows_;
};

// Every stored generation of the run in `db`, in order (the rows replay writes).
AnytimeTrace stored_anytime(const MoldOptimizer& optimizer, const store::RunStore& db);

}  // namespace mtcs::run
