#include "thermal/kernels/segment_potential.h"

#include <cmath>

namespace mtcs::thermal {

SegmentField segment_field(const Vec3& a, const Vec3& b, const Vec3& s) {
  SegmentField f;
  const Vec3 axis = b - a;
  const double length = axis.norm();
  const Vec3 w = s - a;
  const double r_a = w.norm();
  if (length == 0) {  // a point: no length, no potential
    return f;
  }
  const Vec3 u = axis / length;
  const double t_a = w.dot(u);
  const double t_b = t_a - length;
  f.rho = w - t_a * u;
  const double rho2 = f.rho.squaredNorm();
  const double r_b = (s - b).norm();
  // r_a - t_a and r_b + t_b, each written so that no two near-equal numbers are subtracted.
  const double A = t_a > 0 ? rho2 / (r_a + t_a) : r_a - t_a;
  const double B = t_b < 0 ? rho2 / (r_b - t_b) : r_b + t_b;
  f.phi = std::log1p(2 * length / (A + B));
  // (t_a/r_a - t_b/r_b) / rho^2, the same way: beyond an end both ratios are near +-1.
  if (t_b >= 0) {
    f.dipole_factor = 1 / (r_b * (r_b + t_b)) - 1 / (r_a * (r_a + t_a));
  } else if (t_a <= 0) {
    f.dipole_factor = 1 / (r_a * (r_a - t_a)) - 1 / (r_b * (r_b - t_b));
  } else {
    f.dipole_factor = (t_a / r_a - t_b / r_b) / rho2;
  }
  return f;
}

double segment_potential(const Vec3& a, const Vec3& b, const Vec3& s) {
  return segment_field(a, b, s).phi;
}

TriangleSource::TriangleSource(const Vec3& a, const Vec3& b, const Vec3& c) : corner_{a, b, c} {
  const Vec3 normal_area = (b - a).cross(c - a);
  twice_area_ = normal_area.norm();
  if (twice_area_ == 0) return;
  normal_ = normal_area / twice_area_;
  for (int i = 0; i < 3; ++i) {
    const Vec3 edge = corner_[(i + 1) % 3] - corner_[i];
    length_[i] = edge.norm();
    if (length_[i] == 0) continue;
    along_[i] = edge / length_[i];
    out_[i] = along_[i].cross(normal_);
  }
}

double TriangleSource::potential(const Vec3& s) const {
  // Wilton et al. (1984) / Graglia (1993): at height d over the triangle's plane, the sum over
  // the edges of P0 log((R+ + l+)/(R- + l-)) minus |d| times the solid angle the triangle
  // subtends at s. The solid angle in one atan2 (Van Oosterom & Strackee 1983) rather than two
  // atans per edge: half the time, the same accuracy (relative 1e-7 at worst, near an edge's
  // line, as before; checked against long double).
  if (twice_area_ == 0) return 0;
  const Vec3 corner[3] = {corner_[0] - s, corner_[1] - s, corner_[2] - s};
  const double d = -corner[0].dot(normal_);
  const double ad = std::abs(d);
  const double r[3] = {corner[0].norm(), corner[1].norm(), corner[2].norm()};
  double sum_log = 0;
  for (int i = 0; i < 3; ++i) {
    if (length_[i] == 0) continue;
    const int j = (i + 1) % 3;
    const double P0 = corner[i].dot(out_[i]);  // > 0 when s projects on the inner side
    const double l_minus = corner[i].dot(along_[i]), l_plus = corner[j].dot(along_[i]);
    const double R0sq = P0 * P0 + d * d;
    // s on this edge's line (a corner of the triangle, or on an edge) to rounding: the term
    // vanishes (P0 log(1/P0) -> 0); left in, a corner's log(x / 0) would give inf or NaN.
    if (P0 == 0 || R0sq <= 1e-24 * length_[i] * length_[i]) continue;
    // (R+ + l+)/(R- + l-), each sum formed only where it does not cancel: (R + l)(R - l) = R0^2
    // turns a negative l's sum into a quotient.
    double ratio;
    if (l_minus >= 0) ratio = (r[j] + l_plus) / (r[i] + l_minus);
    else if (l_plus <= 0) ratio = (r[i] - l_minus) / (r[j] - l_plus);
    else ratio = (r[j] + l_plus) * (r[i] - l_minus) / R0sq;
    sum_log += P0 * std::log(ratio);
  }
  if (ad == 0) return sum_log;
  // tan(omega / 2) = |R1 . (R2 x R3)| / (r1 r2 r3 + (R1.R2) r3 + (R1.R3) r2 + (R2.R3) r1), and
  // the triple product is |d| times twice the area, free of cancellation.
  const double den = r[0] * r[1] * r[2] + corner[0].dot(corner[1]) * r[2] + corner[0].dot(corner[2]) * r[1] +
                     corner[1].dot(corner[2]) * r[0];
  return sum_log - ad * 2 * std::atan2(ad * twice_area_, den);
}

Vec3 TriangleSource::gradient(const Vec3& s) const {
  if (twice_area_ == 0) return Vec3::Zero();
  const Vec3 corner[3] = {corner_[0] - s, corner_[1] - s, corner_[2] - s};
  const double d = -corner[0].dot(normal_);
  const double r[3] = {corner[0].norm(), corner[1].norm(), corner[2].norm()};
  Vec3 g = Vec3::Zero();
  for (int i = 0; i < 3; ++i) {
    if (length_[i] == 0) continue;
    const int j = (i + 1) % 3;
    const double P0 = corner[i].dot(out_[i]);
    const double l_minus = corner[i].dot(along_[i]), l_plus = corner[j].dot(along_[i]);
    const double R0sq = P0 * P0 + d * d;
    double ratio;
    if (l_minus >= 0) ratio = (r[j] + l_plus) / (r[i] + l_minus);
    else if (l_plus <= 0) ratio = (r[i] - l_minus) / (r[j] - l_plus);
    else if (R0sq > 1e-24 * length_[i] * length_[i]) ratio = (r[j] + l_plus) * (r[i] - l_minus) / R0sq;
    else continue;  // on the edge itself: the log diverges, its principal value is the caller's
    g -= std::log(ratio) * out_[i];
  }
  const double ad = std::abs(d);
  if (ad <= 1e-12 * std::sqrt(twice_area_)) return g;
  const double den = r[0] * r[1] * r[2] + corner[0].dot(corner[1]) * r[2] + corner[0].dot(corner[2]) * r[1] +
                     corner[1].dot(corner[2]) * r[0];
  const double omega = 2 * std::atan2(ad * twice_area_, den);
  return g - (d > 0 ? omega : -omega) * normal_;
}

double triangle_potential(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& s) {
  return TriangleSource(a, b, c).potential(s);
}

}  // namespace mtcs::thermal
