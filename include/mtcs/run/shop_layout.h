#pragma once
// The layout a shop receives (`best.layout.yaml`, the replay's front layouts): waypoints rounded
// to a stated tolerance (default 0.01 mm), repeated waypoints dropped and waypoints on a straight
// run merged, as long as the drilling plan stays the one that was found. Coordinates on a block
// face stay exact, so that ports stay on their faces. The written layout is the one re-scored.

#include "mtcs/mold/genome.h"
#include "mtcs/mold/layout.h"
#include "mtcs/mold/scene.h"
#include "mtcs/run/mold_problem.h"

namespace mtcs::run {

inline constexpr double kCoordinateTolerance = 0.01;  // mm

mold::Genome shop_layout(const mold::Scene& scene, const mold::Genome& genome, double tolerance = kCoordinateTolerance);

// The same, kept feasible: a layout found at a clearance's limit can lose a few micrometres to
// the rounding and be written infeasible (issue 16: 4 of 7 runs on the first-mold part). Then
// holes are shifted by one tolerance step across their axis, one at a time, while the violation
// falls, until the written layout is feasible again (or no step helps: it is written as rounded).
mold::Genome shop_layout(const MoldProblem& problem, const mold::Scene& scene, const mold::Genome& genome,
                         double tolerance = kCoordinateTolerance);

// The drilling plan for the hole tables (bores.csv, holes.csv, bores.stl): hole ends, lengths
// and dead ends rounded to the tolerance (the drill point's overshoot is not a round number).
mold::Layout shop_plan(const mold::Layout& layout, double tolerance = kCoordinateTolerance);

}  // namespace mtcs::run
