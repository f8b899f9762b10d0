#pragma once
// Exact, upper-bounded distance between a SOLID cylinder and a filled triangle.
//
// Method (docs/distance-kernel.md, "Cylinder vs triangle"): the closest pair of two convex sets
// lies on features. Either the triangle point is on an edge, which is the cylinder-cylinder
// kernel against a radius-0 cylinder (the edge), or it is inside the triangle, and then the
// cylinder point is the rim point nearest the triangle's plane (closed form; a disk or a shell
// parallel to the plane has a closest pair on a rim or an edge as well). Intersection: an edge
// meets the cylinder, the axis crosses the triangle, or a rim crosses the plane inside it; when
// none of them does, the two are disjoint. Cheap lower bounds (beyond an end plane; the axis'
// distance to the plane minus the radius) end the query early when they reach the upper bound.

#include <limits>

#include "mtcs/geometry/cylinder_distance.h"
#include "mtcs/geometry/primitives.h"

namespace mtcs::geometry {

struct Triangle {
  Vec3 a;
  Vec3 b;
  Vec3 c;
};

struct TriangleDistanceResult {
  // Exact distance (0 when they touch or intersect), or with `bounded` a proven lower bound
  // >= upper_bound.
  double distance = 0;
  Vec3 on_cylinder = Vec3::Zero();  // witnesses; unspecified when bounded
  Vec3 on_triangle = Vec3::Zero();
  bool bounded = false;
  // Edges whose distance the result includes (bit k: the edge from corner k to corner k + 1).
  unsigned edges_examined = 0;

  bool intersecting() const { return !bounded && distance == 0; }
};

// `request.upper_bound` and `request.tolerance` as in the cylinder-cylinder kernel; the other
// fields are passed on to it for the edges. `skip_edges` (same bits as edges_examined) leaves
// out edges the caller has examined already (in a mesh every edge belongs to two triangles): the
// result is then that of the triangle without them.
TriangleDistanceResult distance(const Cylinder& cylinder, const Triangle& triangle,
                                const DistanceRequest& request = {}, unsigned skip_edges = 0);

}  // namespace mtcs::geometry
