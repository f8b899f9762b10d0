#pragma once
// Whether two closed triangles share a point, decided exactly for double coordinates, and the
// shared part as a segment for reports and drawings.
//
// The verdict uses orientation signs only (exact_predicates.h), as Guigue and Devillers'
// test does: the sides of each triangle's corners of the other's plane, then two orientations
// that compare the segments both triangles cut from the planes' common line. Coplanar pairs are
// decided in 2-D (edge crossings, a corner inside the other) on the
// coordinate plane the normal is most aligned with. Triangles must not be degenerate.

#include <array>

#include "mtcs/geometry/primitives.h"

namespace mtcs::mesh {

using geometry::Vec3;
using Triangle = std::array<Vec3, 3>;

// Exact: true when the closed triangles share at least one point.
bool triangles_intersect(const Triangle& a, const Triangle& b);

struct TriangleIntersection {
  bool intersects = false;
  bool coplanar = false;  // both triangles lie in one plane
  // The common part: a segment (p == q for a single point). For coplanar triangles, whose common
  // part is a polygon, the two of its corners furthest apart. Constructed in floating point.
  Vec3 p = Vec3::Zero();
  Vec3 q = Vec3::Zero();
};

// The exact verdict of triangles_intersect and, when they meet, the common segment.
TriangleIntersection intersect_triangles(const Triangle& a, const Triangle& b);

// Distance between two closed triangles (0 when they meet).
double triangle_distance(const Triangle& a, const Triangle& b);

}  // namespace mtcs::mesh
