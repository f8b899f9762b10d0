#pragma once
// Geometric primitives shared by every kernel. Bores and cylindrical keep-outs are solid right
// circular cylinders given by their axis segment and radius.

#include <Eigen/Core>
#include <Eigen/Geometry>  // cross products, unitOrthogonal

namespace mtcs::geometry {

using Vec3 = Eigen::Vector3d;

struct Segment {
  Vec3 p0;
  Vec3 p1;
};

// A circle in 3-D; as a disk it is the filled circle. `normal` must be a unit vector.
struct Circle {
  Vec3 center;
  Vec3 normal;
  double radius;
};

// Solid right circular cylinder: every point within `radius` of the axis segment p0 -> p1,
// measured perpendicular to the axis, and between the two end planes. A zero-length axis has no
// orientation; it is treated as a disk with normal +z.
struct Cylinder {
  Vec3 p0;
  Vec3 p1;
  double radius;
};

// Scale S of a pair, as the certified cases define it: the largest of the two axis lengths,
// the two radii and the distance between the axis midpoints. Errors are judged against
// max(1, S).
double pair_scale(const Cylinder& a, const Cylinder& b);

// True when every coordinate and radius is finite and both radii are >= 0.
bool is_valid(const Cylinder& c);

}  // namespace mtcs::geometry
