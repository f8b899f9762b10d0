#pragma once
// The genotype of a cooling layout (shared/notes/mtcs_literature.md 7.1): circuits, each a chain
// of waypoints from an inlet on a block face to an outlet on a block face, with one diameter.

#include <vector>

#include "mtcs/geometry/primitives.h"

namespace mtcs::mold {

struct Circuit {
  std::vector<geometry::Vec3> waypoints;  // inlet first, outlet last
  double diameter = 8;
};

struct Genome {
  std::vector<Circuit> circuits;
};

}  // namespace mtcs::mold
