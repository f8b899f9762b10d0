#pragma once
// Exact, upper-bounded distance between a SOLID cylinder and a solid axis-aligned box: the
// primitive cavity and block parts. Not the capsule (axis distance minus radius), which is short
// by up to the radius where a flat end faces the box.

#include "mtcs/geometry/cylinder_triangle_distance.h"
#include "mtcs/geometry/triangle_distance.h"

namespace mtcs::geometry {

// 0 when the cylinder touches, crosses or lies inside the box; witnesses as for triangles.
TriangleDistanceResult distance(const Cylinder& cylinder, const Box& box, const DistanceRequest& request = {});

}  // namespace mtcs::geometry
