#include "mtcs/geometry/primitives.h"

#include <algorithm>
#include <cmath>

namespace mtcs::geometry {

double pair_scale(const Cylinder& a, const Cylinder& b) {
  const Vec3 ma = (a.p0 + a.p1) / 2, mb = (b.p0 + b.p1) / 2;
  return std::max({(a.p1 - a.p0).norm(), (b.p1 - b.p0).norm(), a.radius, b.radius, (ma - mb).norm()});
}

bool is_valid(const Cylinder& c) {
  return c.p0.allFinite() && c.p1.allFinite() && std::isfinite(c.radius) && c.radius >= 0;
}

}  // namespace mtcs::geometry
