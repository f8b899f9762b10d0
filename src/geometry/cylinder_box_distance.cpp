// The box's surface as 12 triangles through the cylinder-triangle kernel, nearest faces first so
// that the upper bound tightens early; a cylinder inside the box (no surface contact) is found by
// its axis midpoint, which then lies in the box.

#include "mtcs/geometry/cylinder_box_distance.h"

#include <algorithm>
#include <array>

namespace mtcs::geometry {

TriangleDistanceResult distance(const Cylinder& cylinder, const Box& box, const DistanceRequest& request) {
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
