#pragma once
// Orientation signs that are exact for double inputs: evaluated in floating point with
// Shewchuk's static error bound, and exactly (CGAL's filtered exact kernel, in
// src/mesh/exact_predicates.cpp only) when the bound cannot decide. Near-coplanar and
// near-collinear configurations, which decide touching and coplanar contact, never go wrong.

#include "mtcs/geometry/primitives.h"

namespace mtcs::mesh {

using geometry::Vec3;

// Sign of ((b - a) x (c - a)) . (d - a): +1 when d lies on the side the normal of the
// counter-clockwise triangle (a, b, c) points to, -1 on the other side, 0 on its plane.
int orient3d(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

// Sign of (b - a) x (c - a) in the plane: +1 when a, b, c turn counter-clockwise.
int orient2d(double ax, double ay, double bx, double by, double cx, double cy);

}  // namespace mtcs::mesh
