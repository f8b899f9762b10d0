#pragma once
// Point-in-solid by the parity of a ray's crossings, for both hierarchies of the mesh module
// (the bore BVH and the interference BVH): a crossing within rounding of an edge or vertex may
// be counted twice or not at all, so such a ray is cast again along another direction.

#include <array>
#include <cmath>
#include <limits>

#include "mtcs/geometry/triangle_distance.h"

namespace mtcs::mesh::detail {

using geometry::Box;
using geometry::Vec3;

inline bool ray_meets_box(const Vec3& o, const Vec3& inv_d, const Box& b) {
  double t0 = 0, t1 = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    double a = (b.min[k] - o[k]) * inv_d[k], c = (b.max[k] - o[k]) * inv_d[k];
    if (a > c) std::swap(a, c);
    t0 = std::max(t0, a), t1 = std::min(t1, c);
  }
  return t0 <= t1;
}

// Moeller-Trumbore for parity counting: 1 crossed, 0 missed, -1 too close to call (the ray
// passes within rounding of an edge or a vertex, or the origin lies on the plane).
inline int ray_crossing(const Vec3& o, const Vec3& d, const std::array<Vec3, 3>& t) {
  const Vec3 e1 = t[1] - t[0], e2 = t[2] - t[0];
  const Vec3 p = d.cross(e2);
  const double det = e1.dot(p);
  const double eps = 1e-12;
  if (std::abs(det) <= eps * e1.norm() * e2.norm()) return 0;  // ray parallel to the plane
  const double inv = 1 / det;
  const Vec3 s = o - t[0];
  const double u = s.dot(p) * inv;
  const Vec3 q = s.cross(e1);
  const double v = d.dot(q) * inv;
  const double along = e2.dot(q) * inv;
  if (u < -eps || v < -eps || u + v > 1 + eps || along < -eps * (s.norm() + 1)) return 0;
  if (u <= eps || v <= eps || u + v >= 1 - eps || along <= eps * (s.norm() + 1)) return -1;
  return 1;
}

// Whether p is inside: `visit(p, d, on_triangle)` must call on_triangle(corners) for at least
// every triangle the ray p + t d (t > 0) may cross.
template <class Visit>
bool inside_by_parity(const Vec3& p, Visit&& visit) {
  // Directions unlikely to graze edges of CAD meshes (along no axis or diagonal).
  static const std::array<Vec3, 3> directions{Vec3(0.5390, 0.6187, 0.5716).normalized(),
                                              Vec3(-0.7071, 0.3123, 0.6349).normalized(),
                                              Vec3(0.2211, -0.8567, 0.4663).normalized()};
  int crossings = 0;
  for (const Vec3& d : directions) {
    crossings = 0;
    bool ambiguous = false;
    visit(p, d, [&](const std::array<Vec3, 3>& t) {
      const int c = ray_crossing(p, d, t);
      if (c < 0) ambiguous = true;
      else crossings += c;
    });
    if (!ambiguous) break;
  }
  return crossings % 2 == 1;
}

}  // namespace mtcs::mesh::detail
