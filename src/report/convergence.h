#pragma once
// The run's progress per stored generation, for the convergence charts: evaluations, the best
// and median scalarised value, the feasible share and the hypervolume of the feasible front.

#include "mtcs/mold/mold_spec.h"
#include "mtcs/opt/problem.h"
#include "mtcs/run/anytime_trace.h"
#include "mtcs/store/run_store.h"
#include "scene_json.h"

namespace mtcs::report {

// The hypervolume is taken in scaled objectives (objective / its scale in the spec) against the
// run's reference point `scaled_ref` (run::AnytimeTrace::reference: summary.json's and replay's),
// so that the page, replay and summary.json give one scale; `hv_ref` gives it.
// The best is the problem's best member (run::best_rank), not the stored rank 0 (SMS-EMOA's order).
Json convergence_json(const store::RunStore& db, const mold::MoldSpec& spec, const std::vector<std::string>& objectives,
                      const opt::Problem& problem, const std::vector<double>& scaled_ref);

// The anytime curves (the rows of replay's anytime.csv): per stored generation evaluations,
// seconds, the best feasible weighted objective and the feasible front's hypervolume, each also
// as the best so far, against the trace's reference point (scaled; SMS-EMOA's is summary.json's):
// a generation without a feasible layout has best null.
Json anytime_json(const run::AnytimeTrace& trace);

}  // namespace mtcs::report
