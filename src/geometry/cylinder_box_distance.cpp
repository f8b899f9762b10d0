// An axis-parallel cylinder by a closed form. Any other: the box's surface as 12 triangles
// through the cylinder-triangle kernel, nearest faces first so that the upper bound tightens
// early; a cylinder inside the box (no surface contact) is found by its axis midpoint, which then
// lies in the box.

#include "mtcs/geometry/cylinder_box_distance.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace mtcs::geometry {
namespace {

// A cylinder along coordinate axis a and a box are products of an interval along a and a disc
// (a rectangle) across it, so their squared distance is the intervals' squared gap plus the
// disc's to the rectangle: a closed form for the axis-parallel bores most molds drill.
TriangleDistanceResult axis_parallel(const Cylinder& cylinder, const Box& box, int a) {
  const int u = (a + 1) % 3, v = (a + 2) % 3;
  TriangleDistanceResult r;
  // Along a: the gap between [c0, c1] and the box's interval, and a nearest pair of coordinates.
  const double c0 = std::min(cylinder.p0[a], cylinder.p1[a]), c1 = std::max(cylinder.p0[a], cylinder.p1[a]);
  double on_cylinder = 0, on_box = 0;
  if (c1 < box.min[a]) on_cylinder = c1, on_box = box.min[a];
  else if (c0 > box.max[a]) on_cylinder = c0, on_box = box.max[a];
  else on_cylinder = on_box = (std::max(c0, box.min[a]) + std::min(c1, box.max[a])) / 2;
  // Across: the rectangle's point nearest the axis, and the disc's point nearest that.
  const double cu = cylinder.p0[u], cv = cylinder.p0[v];
  const double qu = std::clamp(cu, box.min[u], box.max[u]), qv = std::clamp(cv, box.min[v], box.max[v]);
  const double across = std::hypot(qu - cu, qv - cv);
  const double gap_across = std::max(across - cylinder.radius, 0.0);
  r.on_triangle[a] = on_box, r.on_triangle[u] = qu, r.on_triangle[v] = qv;
  r.on_cylinder[a] = on_cylinder;
  if (gap_across > 0) {
    r.on_cylinder[u] = cu + cylinder.radius * (qu - cu) / across;
    r.on_cylinder[v] = cv + cylinder.radius * (qv - cv) / across;
  } else {
    r.on_cylinder[u] = qu, r.on_cylinder[v] = qv;  // within the disc
  }
  r.distance = std::hypot(on_cylinder - on_box, gap_across);
  return r;
}

}  // namespace

TriangleDistanceResult distance(const Cylinder& cylinder, const Box& box, const DistanceRequest& request) {
  // Exactly axis-parallel (two coordinates equal at both ends): the closed form.
  for (int a = 0; a < 3 && is_valid(cylinder); ++a) {
    const int u = (a + 1) % 3, v = (a + 2) % 3;
    if (cylinder.p0[a] != cylinder.p1[a] && cylinder.p0[u] == cylinder.p1[u] && cylinder.p0[v] == cylinder.p1[v]) {
      TriangleDistanceResult r = axis_parallel(cylinder, box, a);
      r.bounded = r.distance >= request.upper_bound;
      return r;
    }
  }
  // The capsule's distance never exceeds the cylinder's: when it reaches the bound, so does the
  // answer, at the price of one segment-box distance (most bores of a layout end here).
  const double capsule = segment_box_distance(cylinder.p0, cylinder.p1, box) - cylinder.radius;
  if (capsule >= request.upper_bound) {
    TriangleDistanceResult far;
    far.distance = capsule;
    far.bounded = true;
    return far;
  }
  const Vec3 mid = (cylinder.p0 + cylinder.p1) / 2;
  if (box.contains(mid)) {
    TriangleDistanceResult inside;
    inside.on_cylinder = inside.on_triangle = mid;
    return inside;
  }
  // Face k: axis k / 2, at min (k even) or max (k odd); its gap to the cylinder's bounding box
  // orders the search.
  const Vec3 r = Vec3::Constant(cylinder.radius);
  const Vec3 lo = cylinder.p0.cwiseMin(cylinder.p1) - r, hi = cylinder.p0.cwiseMax(cylinder.p1) + r;
  std::array<std::pair<double, int>, 6> faces;
  for (int k = 0; k < 6; ++k) {
    const int axis = k / 2;
    const double gap = k % 2 == 0 ? lo[axis] - box.min[axis] : box.max[axis] - hi[axis];
    faces[std::size_t(k)] = {-gap, k};  // the face the cylinder lies most beyond comes first
  }
  std::sort(faces.begin(), faces.end());
  TriangleDistanceResult best;
  best.distance = request.upper_bound;
  best.bounded = true;
  DistanceRequest rq = request;
  for (const auto& [order, k] : faces) {
    const int axis = k / 2, u = (axis + 1) % 3, v = (axis + 2) % 3;
    const bool lower = k % 2 == 0;  // a plain local: clang 14 cannot capture structured bindings
    const auto corner = [&](double su, double sv) {
      Vec3 p;
      p[axis] = lower ? box.min[axis] : box.max[axis];
      p[u] = su;
      p[v] = sv;
      return p;
    };
    const Vec3 a = corner(box.min[u], box.min[v]), b = corner(box.max[u], box.min[v]);
    const Vec3 c = corner(box.max[u], box.max[v]), d = corner(box.min[u], box.max[v]);
    for (const Triangle& t : {Triangle{a, b, c}, Triangle{a, c, d}}) {
      const TriangleDistanceResult res = distance(cylinder, t, rq);
      if (res.bounded || res.distance >= best.distance) continue;
      best = res;
      if (best.distance == 0) return best;
      rq.upper_bound = best.distance;
    }
  }
  return best;
}

}  // namespace mtcs::geometry
