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
// Lower bounds for the early exit, cheap ones only (the edges' own pretests bound the rest):
// how far the triangle lies beyond an end plane, and the axis' distance to the triangle's plane.

#include "mtcs/geometry/cylinder_triangle_distance.h"

#include <algorithm>
#include <cmath>

#include "detail/real.h"
#include "mtcs/geometry/triangle_distance.h"

namespace mtcs::geometry {
namespace {

using detail::quad;
using detail::V3;

// Heights of the axis ends over the triangle's plane (unit normal n), the rims' half height range
// (reach), and each rim's gap to the plane, |h_k| - reach. Those decide contact, so when one of
// them lies within 1e-10 S of zero they are recomputed from the same doubles in 113 bits, and
// within 1e-24 S of zero they count as zero (the cylinder kernel's convention).
struct PlaneHeights {
  double h[2];
  double reach;
  double gap[2];
};

PlaneHeights plane_heights(const Cylinder& cyl, const Triangle& tri, const Vec3& n, const Vec3& w) {
  PlaneHeights out;
  const double slope = (n - n.dot(w) * w).norm();
  out.reach = cyl.radius * slope;
  out.h[0] = n.dot(cyl.p0 - tri.a), out.h[1] = n.dot(cyl.p1 - tri.a);
  for (int k = 0; k < 2; ++k) out.gap[k] = std::abs(out.h[k]) - out.reach;
  const double scale = std::max({1.0, (cyl.p1 - cyl.p0).norm(), cyl.radius, (cyl.p0 - tri.a).norm(),
                                 (tri.b - tri.a).norm(), (tri.c - tri.a).norm()});
  const double marginal = 1e-10 * scale;
  if (std::min({std::abs(out.h[0]), std::abs(out.h[1]), std::abs(out.gap[0]), std::abs(out.gap[1])}) > marginal)
    return out;
  const auto q = [](const Vec3& v) { return detail::from_eigen<quad>(v); };
  const V3<quad> a = q(tri.a), nq = detail::cross(q(tri.b) - a, q(tri.c) - a);
  const V3<quad> unit = nq * (quad(1) / detail::norm(nq));
  const V3<quad> axis = q(cyl.p1) - q(cyl.p0);
  const quad len = detail::norm(axis);
  const V3<quad> wq = len > 0 ? axis * (quad(1) / len) : V3<quad>{0, 0, 1};
  const quad reach = quad(cyl.radius) * detail::norm(unit - detail::dot(unit, wq) * wq);
  const quad tiny = quad(1e-24) * quad(scale);
  const auto snap = [tiny](quad v) { return detail::abs_(v) <= tiny ? 0.0 : double(v); };
  out.reach = double(reach);
  const quad hq[2] = {detail::dot(unit, q(cyl.p0) - a), detail::dot(unit, q(cyl.p1) - a)};
  for (int k = 0; k < 2; ++k) out.h[k] = snap(hq[k]), out.gap[k] = snap(detail::abs_(hq[k]) - reach);
  return out;
}

// Whether the projection of x along the normal n = (b - a) x (c - a) lies in the closed triangle.
bool projects_inside(const Vec3& x, const Triangle& t, const Vec3& n) {
  return n.dot((t.b - t.a).cross(x - t.a)) >= 0 && n.dot((t.c - t.b).cross(x - t.b)) >= 0 &&
         n.dot((t.a - t.c).cross(x - t.c)) >= 0;
}

TriangleDistanceResult touching(const Vec3& x) { return {0, x, x, false}; }

}  // namespace

TriangleDistanceResult distance(const Cylinder& cyl, const Triangle& tri, const DistanceRequest& request,
                                unsigned skip_edges) {
  const double upper = request.upper_bound;
  // How far the triangle lies beyond an end plane.
  const Vec3 axis = cyl.p1 - cyl.p0;
  const double len = axis.norm();
  const Vec3 w = len > 0 ? Vec3(axis / len) : Vec3::UnitZ();
  const double ta = w.dot(tri.a - cyl.p0), tb = w.dot(tri.b - cyl.p0), tc = w.dot(tri.c - cyl.p0);
  const double slab = std::max(-std::max({ta, tb, tc}), std::min({ta, tb, tc}) - len);
  if (slab >= upper) return {slab, Vec3::Zero(), Vec3::Zero(), true};
  // The axis against the triangle's plane: crossing it inside the triangle is an intersection;
  // staying on one side bounds the distance from below (the plane holds the triangle).
  const Vec3 normal = (tri.b - tri.a).cross(tri.c - tri.a);
  const double area2 = normal.norm();
  double lower = slab;
  PlaneHeights heights{};
  if (area2 > 0) heights = plane_heights(cyl, tri, normal / area2, w);
  if (area2 > 0) {
    const double h0 = heights.h[0], h1 = heights.h[1];
    if ((h0 > 0 && h1 > 0) || (h0 < 0 && h1 < 0)) {
      lower = std::max(lower, std::min(std::abs(h0), std::abs(h1)) - cyl.radius);
    } else if (h0 != h1) {
      const Vec3 x = cyl.p0 + (h0 / (h0 - h1)) * axis;
      if (projects_inside(x, tri, normal)) return touching(x);
    } else if (segment_triangle_distance(cyl.p0, cyl.p1, tri.a, tri.b, tri.c) == 0) {
      return touching(cyl.p0);  // the axis lies in the plane and meets the triangle
    }
  }
  if (lower >= upper) return {lower, Vec3::Zero(), Vec3::Zero(), true};

  TriangleDistanceResult best{std::numeric_limits<double>::infinity(), Vec3::Zero(), Vec3::Zero(), false};
  // Rims against the triangle's interior (a zero-area triangle has none: its edges cover it).
  if (area2 > 0) {
    const Vec3 n = normal / area2;
    const Vec3 across = n - n.dot(w) * w;  // the plane's steepest direction within the end disks
    const double slope = across.norm();
    const Vec3 u = slope > 0 ? Vec3(across / slope) : Vec3::Zero();
    const double reach = heights.reach;  // half the height range over a rim
    for (int k = 0; k < 2; ++k) {
      const Vec3& center = k == 0 ? cyl.p0 : cyl.p1;
      const double h = heights.h[k];
      if (heights.gap[k] <= 0) {
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
      const double gap = heights.gap[k];
      if (gap < best.distance && projects_inside(x, tri, normal))
        best = {gap, x, x - std::copysign(gap, h) * n, false};
    }
  }
  // Edges against the solid cylinder.
  const std::pair<const Vec3&, const Vec3&> edges[3] = {{tri.a, tri.b}, {tri.b, tri.c}, {tri.c, tri.a}};
  unsigned examined = 0;
  for (unsigned k = 0; k < 3; ++k) {
    if (skip_edges >> k & 1u) continue;
    examined |= 1u << k;
    DistanceRequest edge_request = request;
    edge_request.upper_bound = std::min(upper, best.distance);
    const DistanceResult d = geometry::distance(cyl, Cylinder{edges[k].first, edges[k].second, 0.0}, edge_request);
    if (d.bounded || !(d.distance < best.distance)) continue;
    best = {d.distance, d.witness_a, d.witness_b, false};
    if (d.intersecting()) break;
  }
  best.edges_examined = examined;
  if (best.intersecting()) return best;
  if (!(best.distance < upper)) return {std::max(lower, upper), Vec3::Zero(), Vec3::Zero(), true, examined};
  return best;
}

}  // namespace mtcs::geometry
