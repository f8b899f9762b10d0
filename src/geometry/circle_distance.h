#pragma once
// Distances from a circle (a cylinder's rim) to a line, a disk and another circle.
//
// Method: not Vranek's polynomial deflation. Each query minimises the closed-form distance from
// the point at angle theta on the circle to the other element: a periodic sampling brackets
// every basin, Brent's method refines each to the tolerance. The squared distance to a line is a
// trigonometric polynomial of degree 2 (at most two minima), to a circle or disk a piecewise
// smooth function with at most four; 24 samples bracket them all in every certified case. It
// avoids root finding on ill-conditioned quartics/octics (the instability the source paper
// reports in Vranek's circle-line code, and its radius < 1 failure) and makes the tolerance a
// direct bound on the angular error. See docs/distance-kernel.md.

#include "mtcs/geometry/primitives.h"

namespace mtcs::geometry {

struct CircleClosest {
  double distance;
  Vec3 point_on_circle;
  Vec3 point_on_other;
};

struct CircleQuery {
  // Stop refining when the angular bracket, times the radius, is below tolerance * max(1, S).
  double tolerance = 1e-12;
};

// Infinite line through `origin` along `direction` (any non-zero length).
CircleClosest circle_line_distance(const Circle& c, const Vec3& origin, const Vec3& direction,
                                   const CircleQuery& q = {});
CircleClosest circle_circle_distance(const Circle& a, const Circle& b, const CircleQuery& q = {});
// Distance from the circle (a curve) to the filled disk.
CircleClosest circle_disk_distance(const Circle& c, const Circle& disk, const CircleQuery& q = {});

}  // namespace mtcs::geometry
