#pragma once
// What `mtcs optimize` leaves beside run.sqlite: best.layout.yaml (editable, re-scorable),
// bores.csv, holes.csv (the shop's hole table), bores.stl, summary.json (with the best layout's
// violations and, with a coolant flow, each circuit's hydraulics and heat), and for SMS-EMOA front.csv.

#include <optional>
#include <string>
#include <vector>

#include "mtcs/eval/evaluation.h"
#include "mtcs/mold/layout.h"
#include "mtcs/run/mold_run.h"
#include "mtcs/run/polish.h"
#include "mtcs/run/shop_layout.h"

namespace mtcs::run {

struct RunOutcome {
  const opt::Generation& last;
  opt::Score best;              // the best layout's score (after the polish, if it improved)
  mold::Genome genome;          // the best layout
  double seconds = 0;
  std::string mold_path;
  std::optional<Polished> polished;  // when a polish ran
  double before_polish = 0;          // the objective it started from
  bool interrupted = false;          // stopped before the budget (Ctrl-C): best so far
  double tolerance = kCoordinateTolerance;  // mm, of the written coordinates (genome: already rounded)
  eval::Evaluation evaluation;  // the best layout's as mtcs evaluate scores it: its violations, each bore's heat
};

// What a designer must hear about a Pareto front: hypervolume 0 (every point outside the
// reference point) or a front of a single design. Empty for the ES and for a healthy front.
std::vector<std::string> front_warnings(const MoldOptimizer& optimizer, const opt::Generation& last);

// Writes the files into out_dir (each whole or not at all); returns the best layout decoded.
mold::Layout write_run_outputs(const std::string& out_dir, const mold::Scene& scene, const MoldOptimizer& optimizer,
                               const std::vector<std::string>& objective_names, std::uint64_t seed,
                               const RunOutcome& outcome);

}  // namespace mtcs::run
