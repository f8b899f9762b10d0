#pragma once
// The potentials the line-sink tiers superpose, free of the 1/(4 pi k) factor: a uniform line
// source on a segment, a uniform transverse line dipole on it, and a uniform source on a planar
// triangle. Every form here is cancellation-free (notes 4.4): no difference of nearly equal
// distances is ever formed, so a field point 1e-7 mm from a 1000 mm segment, or 1e4 mm from the
// origin, keeps full precision.

#include "mtcs/geometry/primitives.h"

namespace mtcs::thermal {

using geometry::Vec3;

// Phi(s) = integral over the segment a -> b of dl / |s - y(l)| = log1p(2L / D), D = r_a + r_b - L
// computed as A + B without cancellation. Infinite on the segment itself.
double segment_potential(const Vec3& a, const Vec3& b, const Vec3& s);

// Both kernels of a segment at one field point, sharing the distances.
struct SegmentField {
  double phi = 0;  // the line source: segment_potential
  // The line dipole: integral of (s - y(l)) . p / |s - y(l)|^3 dl for a unit transverse moment p
  // (p . axis = 0) equals dipole_factor * (p . rho), rho the transverse offset of s from the axis.
  double dipole_factor = 0;
  Vec3 rho = Vec3::Zero();
};
SegmentField segment_field(const Vec3& a, const Vec3& b, const Vec3& s);

// Integral over the triangle of dA / |s - y|: the potential of a unit uniform surface source.
// Closed form (edge sums of logs and a solid-angle term), finite everywhere, including points
// in the triangle's plane and on the triangle; 0 for a degenerate triangle.
double triangle_potential(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& s);

// The same for one triangle at many points: its plane and edges are taken once.
class TriangleSource {
 public:
  TriangleSource() = default;  // degenerate: potential 0 everywhere
  TriangleSource(const Vec3& a, const Vec3& b, const Vec3& c);
  double potential(const Vec3& s) const;
  // Its gradient at s: -sign(d) Omega n - sum over the edges of out_e log(...), d the height over
  // the plane, Omega the solid angle. In the plane (|d| below 1e-12 of the size) the normal term
  // is left out: on the triangle, the principal value; the jump is the caller's (+-1/2).
  Vec3 gradient(const Vec3& s) const;
  const Vec3& normal() const { return normal_; }
  const Vec3& corner(int i) const { return corner_[i]; }
  double area() const { return 0.5 * twice_area_; }

 private:
  Vec3 corner_[3] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  Vec3 normal_ = Vec3::Zero();
  // Per edge i (corner i to corner i + 1): unit direction, in-plane normal pointing out of the
  // triangle, length.
  Vec3 along_[3] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  Vec3 out_[3] = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  double length_[3] = {0, 0, 0};
  double twice_area_ = 0;
};

}  // namespace mtcs::thermal
