// Solid cylinder vs filled triangle. Why these candidates are complete (closest pair (x, y), x on
// the cylinder, y on the triangle, the two disjoint):
//  * y on an edge: the edge's distance to the solid cylinder, which the cylinder-cylinder kernel
//    computes exactly for a radius-0 cylinder;
//  * y inside the triangle: x - y is normal to the plane, so x is a local minimum of the height
//    above the plane over the cylinder. On a rim the height is a sinusoid, minimal at the rim
//    point nearest the plane (closed form). On an end disk's interior or the shell's the height
//    is constant only when they are parallel to the plane, and then the closest pairs form a
//    patch whose boundary reaches a rim or an edge.
// Intersection: if no edge meets the cylinder, the cylinder's section by the plane lies inside
// the triangle; it contains the axis' crossing with the plane if there is one, and otherwise a
// rim crosses the plane (the height over the cylinder is extreme on the rims, and the axis
// stays on one side), whose crossing points are then inside the triangle.

#include "mtcs/geometry/cylinder_triangle_distance.h"

#include <algorithm>
#include <cmath>

#include "mtcs/geometry/triangle_distance.h"

namespace mtcs::geometry {
namespace {

// Whether the projection of x along the normal n = (b - a) x (c - a) lies in the closed triangle.
bool projects_inside(const Vec3& x, const Triangle& t, const Vec3& n) {
  return n.dot((t.b - t.a).cross(x - t.a)) >= 0 && n.dot((t.c - t.b).cross(x - t.b)) >= 0 &&
         n.dot((t.a - t.c).cross(x - t.c)) >= 0;
}

TriangleDistanceResult touching(const Vec3& x) { return {0, x, x, false}; }

}  // namespace

TriangleDistanceResult distance(const Cylinder& cyl, const Triangle& tri, const DistanceRequest& request) {
  const double upper = request.upper_bound;
  // Capsule lower bound; an axis touching the triangle is an intersection.
  const double axis_distance = segment_triangle_distance(cyl.p0, cyl.p1, tri.a, tri.b, tri.c);
  const double lower = axis_distance - cyl.radius;
  if (lower >= upper) return {lower, Vec3::Zero(), Vec3::Zero(), true};
  const Vec3 normal = (tri.b - tri.a).cross(tri.c - tri.a);
  const double area2 = normal.norm();
  if (axis_distance == 0) {
    const double h0 = normal.dot(cyl.p0 - tri.a), h1 = normal.dot(cyl.p1 - tri.a);
    return touching(h0 == h1 ? cyl.p0 : Vec3(cyl.p0 + (h0 / (h0 - h1)) * (cyl.p1 - cyl.p0)));
  }

  TriangleDistanceResult best{std::numeric_limits<double>::infinity(), Vec3::Zero(), Vec3::Zero(), false};
  // Rims against the triangle's interior (a zero-area triangle has none: its edges cover it).
  if (area2 > 0) {
    const Vec3 n = normal / area2;
    const Vec3 axis = cyl.p1 - cyl.p0;
    const double len = axis.norm();
    const Vec3 w = len > 0 ? Vec3(axis / len) : Vec3::UnitZ();
    const Vec3 across = n - n.dot(w) * w;  // the plane's steepest direction within the end disks
    const double slope = across.norm();
    const Vec3 u = slope > 0 ? Vec3(across / slope) : Vec3::Zero();
    const double reach = cyl.radius * slope;  // half the height range over a rim
    for (const Vec3& center : {cyl.p0, cyl.p1}) {
      const double h = n.dot(center - tri.a);
      if (std::abs(h) <= reach) {
        if (reach == 0) continue;  // the disk lies in the plane: the axis test decided it
        // The rim crosses the plane at angles +-alpha from u: inside the triangle means contact.
        const double cos_a = std::clamp(-h / reach, -1.0, 1.0), sin_a = std::sqrt(1 - cos_a * cos_a);
        const Vec3 v = w.cross(u);
        for (const double s : {sin_a, -sin_a}) {
          const Vec3 x = center + cyl.radius * (cos_a * u + s * v);
          if (projects_inside(x, tri, normal)) return touching(x);
        }
        continue;
      }
      // The rim point nearest the plane (the disk centre when the disk is parallel to it).
      const Vec3 x = center - std::copysign(cyl.radius, h) * u;
      const double gap = std::abs(h) - reach;
      if (gap < best.distance && projects_inside(x, tri, normal))
        best = {gap, x, x - std::copysign(gap, h) * n, false};
    }
  }
  // Edges against the solid cylinder.
  for (const auto& [e0, e1] : {std::pair{tri.a, tri.b}, std::pair{tri.b, tri.c}, std::pair{tri.c, tri.a}}) {
    DistanceRequest edge_request = request;
    edge_request.upper_bound = std::min(upper, best.distance);
    const DistanceResult d = geometry::distance(cyl, Cylinder{e0, e1, 0.0}, edge_request);
    if (d.bounded || !(d.distance < best.distance)) continue;
    best = {d.distance, d.witness_a, d.witness_b, false};
    if (d.intersecting()) return best;
  }
  if (!(best.distance < upper)) return {std::max(lower, upper), Vec3::Zero(), Vec3::Zero(), true};
  return best;
}

}  // namespace mtcs::geometry
