#pragma once
// A tool pivoting at a point: closed solid cylinders coaxial with the tool direction d,
// {pivot + t d + w : a <= t <= b, w.d = 0, |w| <= r}, and the sphere grid of directions an
// accessibility map samples.

#include <cmath>
#include <vector>

#include "mtcs/geometry/primitives.h"

namespace mtcs::voxel {

using geometry::Vec3;

struct ToolCylinder {
  double a = 0;  // start along the axis, from the pivot
  double b = 0;  // end, b >= a
  double r = 0;  // radius >= 0
};

using Tool = std::vector<ToolCylinder>;

// Row i: phi_i = (i + 0.5) pi / rows; column j: gamma_j = (j + 0.5) 2 pi / cols;
// d = (sin phi cos gamma, sin phi sin gamma, cos phi).
struct SphereGrid {
  int rows = 32;
  int cols = 32;

  Vec3 direction(int i, int j) const {
    const double phi = (i + 0.5) * M_PI / rows, gamma = (j + 0.5) * 2 * M_PI / cols;
    return {std::sin(phi) * std::cos(gamma), std::sin(phi) * std::sin(gamma), std::cos(phi)};
  }
};

}  // namespace mtcs::voxel
