#include "segment_potential.h"

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

namespace {

// log((R+ + l+) / (R- + l-)) of one edge, R = sqrt(R0^2 + l^2): the sums are formed only where
// no cancellation happens ((R + l)(R - l) = R0^2 turns a negative l into a positive one).
double edge_log(double l_minus, double l_plus, double R_minus, double R_plus, double R0) {
  if (l_minus >= 0) return std::log((R_plus + l_plus) / (R_minus + l_minus));
  if (l_plus <= 0) return std::log((R_minus - l_minus) / (R_plus - l_plus));
  return std::asinh(l_plus / R0) - std::asinh(l_minus / R0);
}

}  // namespace

double triangle_potential(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& s) {
  // Wilton et al. (1984) / Graglia (1993): for the projection p of s on the plane at height d,
  // sum over the edges of P0 log((R+ + l+)/(R- + l-)) - |d| (atan terms: the solid angle).
  const Vec3 normal_area = (b - a).cross(c - a);
  const double twice_area = normal_area.norm();
  if (twice_area == 0) return 0;
  const Vec3 n = normal_area / twice_area;
  const double d = (s - a).dot(n);
  const double ad = std::abs(d);
  const Vec3 p = s - d * n;
  const Vec3 corners[3] = {a, b, c};
  double sum_log = 0, sum_angle = 0;
  for (int i = 0; i < 3; ++i) {
    const Vec3& p0 = corners[i];
    const Vec3& p1 = corners[(i + 1) % 3];
    const Vec3 edge = p1 - p0;
    const double edge_length = edge.norm();
    if (edge_length == 0) continue;
    const Vec3 t = edge / edge_length;
    const Vec3 m = t.cross(n);                  // in-plane, pointing out of the triangle
    const double P0 = (p0 - p).dot(m);          // > 0 when p is on the inner side of the edge
    const double l_minus = (p0 - p).dot(t);
    const double l_plus = (p1 - p).dot(t);
    const double R0sq = P0 * P0 + d * d;
    const double R_minus = (s - p0).norm();
    const double R_plus = (s - p1).norm();
    // s on this edge's line (a corner of the triangle, or on an edge) to rounding: P0 and d
    // vanish and so does the term (P0 log(1/P0) -> 0); left in, rounding turns a corner's
    // log(x / 0) into inf, and two such edges into NaN.
    if (R0sq <= 1e-24 * edge_length * edge_length) continue;
    const double R0 = std::sqrt(R0sq);
    if (P0 != 0) sum_log += P0 * edge_log(l_minus, l_plus, R_minus, R_plus, R0);
    if (ad != 0 && P0 != 0) {
      sum_angle += std::atan(P0 * l_plus / (R0sq + ad * R_plus)) -
                   std::atan(P0 * l_minus / (R0sq + ad * R_minus));
    }
  }
  return sum_log - ad * sum_angle;
}

}  // namespace mtcs::thermal
