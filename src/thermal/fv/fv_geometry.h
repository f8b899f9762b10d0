#pragma once
// Geometry the finite-volume grid needs: where a grid line enters a bore, and how much of a
// face cell a heated triangle covers.

#include <optional>

#include "mtcs/geometry/primitives.h"

namespace mtcs::thermal::fv {

using geometry::Vec3;

// Whether p lies in the solid cylinder (within `radius` of the axis, between the end planes).
bool inside_cylinder(const Vec3& p, const geometry::Cylinder& cylinder);

// Where the ray p + t e (e a unit vector, p outside) first enters the solid cylinder, for
// 0 <= t <= length, and |n . e| there (n the wall's normal): the cosine the film needs. Also
// where it leaves (possibly beyond length) and the cosine there: the entry seen from the
// other end of the link. A tangent (a chord shorter than 1e-9 length) does not enter.
struct Entry {
  double t;
  double cosine;
  double exit;
  double exit_cosine;
};
std::optional<Entry> enter_cylinder(const Vec3& p, const Vec3& e, double length,
                                    const geometry::Cylinder& cylinder);

// Area of the triangle (a, b, c) inside the rectangle [x0, x1] x [y0, y1] (2-D points as x, y).
double triangle_rectangle_overlap(const double a[2], const double b[2], const double c[2], double x0,
                                  double x1, double y0, double y1);

// The part of the triangle (a, b, c) inside the box [lo, hi]: its area and centroid.
struct Piece {
  double area = 0;
  Vec3 centroid = Vec3::Zero();
};
Piece clip_triangle_to_box(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& lo, const Vec3& hi);

}  // namespace mtcs::thermal::fv
