#pragma once
// The reach move (issue 16, target 2): a circuit laid by construction where a layout cools worst.
// The cavity sample farthest from every flow bore is found (eval::WorstCoveredSearch), and a U circuit (the shape
// random_circuit draws) is laid with one leg beside it, starting just outside the sample; the
// pipeline scores the circuit alone and every clearance it violates (cavity, keep-outs, block
// surface) pushes the whole circuit out by the shortfall, until it is feasible or the tries are
// spent. Narrow windows are found this way, not by chance: on the first mold an 8 mm bore reaches
// the central trough only with its axis in a 1 mm band above the part (experiments/defaults).

#include <functional>
#include <optional>
#include <vector>

#include "mtcs/eval/pipeline.h"
#include "mtcs/mold/genome.h"
#include "mtcs/mold/layout.h"
#include "mtcs/opt/rng.h"

namespace mtcs::run {

// The wall distance from p to the nearest flow bore of the circuit as the scene decodes it.
double wall_distance(const mold::Scene& scene, const mold::Circuit& circuit, const geometry::Vec3& p);

struct ReachRequest {
  geometry::Vec3 target;            // the sample to reach
  double better_than = 0;           // the new circuit must come nearer (wall distance, mm)
  double diameter = 8;
  int evaluations = 12;             // pipeline evaluations of the circuit alone, at most
  geometry::Box region;             // where the circuit's other legs may run (around the part)
};

struct Reached {
  std::optional<mold::Circuit> circuit;
  int evaluations = 0;  // pipeline evaluations spent (they count in the optimiser's budget)
};

// A circuit feasible on its own (no violation in the pipeline) whose flow bores come within
// `better_than` of the target, or none after `evaluations` tries. `repair` puts its ports back
// on their faces (MoldProblem::repair).
Reached circuit_reaching(const eval::Pipeline& pipeline, const ReachRequest& request,
                                              const std::function<void(mold::Circuit&)>& repair, opt::Rng& rng);

}  // namespace mtcs::run
