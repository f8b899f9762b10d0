#pragma once
// Local refinement of a layout's coordinates for its fixed topology with NLopt's COBYLA: the
// derivative-free method of the three (BOBYQA, COBYLA, SBPLX) that takes the constraint
// "total violation <= 0" as it is, instead of folding it into a penalty; a feasible start stays
// feasible or the refinement is discarded.
//
// The variables are hole coordinates: with axis-parallel drilling, consecutive waypoints that
// share a coordinate move as one (a hole shifts across its axis), so refining keeps holes
// aligned; ports keep the coordinate that puts them on their face.

#include <string>

#include "mtcs/run/mold_problem.h"
#include "mtcs/mold/scene.h"

namespace mtcs::run {

struct Polished {
  mold::Genome genome;
  opt::Score score;
  int evaluations = 0;
  bool improved = false;
  std::string why_not;  // when not improved: the reason, for the log and summary.json
};

Polished polish(const MoldProblem& problem, const mold::Scene& scene, const mold::Genome& start, int max_evaluations);

}  // namespace mtcs::run
