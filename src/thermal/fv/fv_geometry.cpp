#include "thermal/fv/fv_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mtcs::thermal::fv {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct Interval {
  double lo = -kInf, hi = kInf;
  bool empty() const { return lo > hi; }
};

}  // namespace

bool inside_cylinder(const Vec3& p, const geometry::Cylinder& cylinder) {
  const Vec3 axis = cylinder.p1 - cylinder.p0;
  const double length = axis.norm();
  if (length == 0) return false;
  const Vec3 u = axis / length;
  const Vec3 w = p - cylinder.p0;
  const double s = w.dot(u);
  return s >= 0 && s <= length && (w - s * u).squaredNorm() <= cylinder.radius * cylinder.radius;
}

std::optional<Entry> enter_cylinder(const Vec3& p, const Vec3& e, double length,
                                    const geometry::Cylinder& cylinder) {
  const Vec3 axis = cylinder.p1 - cylinder.p0;
  const double axis_length = axis.norm();
  if (axis_length == 0) return std::nullopt;
  const Vec3 u = axis / axis_length;
  const Vec3 w = p - cylinder.p0;
  const double eu = e.dot(u), wu = w.dot(u);
  const Vec3 e_perp = e - eu * u, w_perp = w - wu * u;

  // Lateral: |w_perp + t e_perp|^2 <= r^2.
  Interval lateral;
  const double qa = e_perp.squaredNorm(), qb = 2 * w_perp.dot(e_perp);
  const double qc = w_perp.squaredNorm() - cylinder.radius * cylinder.radius;
  if (qa <= 1e-14) {
    if (qc > 0) return std::nullopt;  // parallel to the axis and outside
  } else {
    const double disc = qb * qb - 4 * qa * qc;
    if (disc < 0) return std::nullopt;
    // Stable roots: the smaller one from the sum of like signs.
    const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
    double t1 = q / qa, t2 = q != 0 ? qc / q : t1;
    if (t1 > t2) std::swap(t1, t2);
    lateral = {t1, t2};
  }
  // Between the end planes: 0 <= wu + t eu <= axis_length.
  Interval axial;
  if (std::abs(eu) <= 1e-14) {
    if (wu < 0 || wu > axis_length) return std::nullopt;
  } else {
    double t1 = -wu / eu, t2 = (axis_length - wu) / eu;
    if (t1 > t2) std::swap(t1, t2);
    axial = {t1, t2};
  }
  const Interval both{std::max(lateral.lo, axial.lo), std::min(lateral.hi, axial.hi)};
  if (both.empty() || both.hi < 0 || both.lo > length) return std::nullopt;
  // A line that only touches the wall (a tangent) does not enter.
  if (both.hi - both.lo <= 1e-9 * length) return std::nullopt;
  // |n . e| where the line crosses the wall at t: radial on the side wall, axial on an end disk.
  const auto cosine = [&](double t, bool side) {
    if (!side) return std::abs(eu);
    const Vec3 radial = w_perp + t * e_perp;
    const double r = radial.norm();
    return r > 0 ? std::abs(radial.dot(e)) / r : 1.0;
  };
  Entry entry;
  entry.t = std::max(both.lo, 0.0);
  entry.cosine = cosine(entry.t, lateral.lo >= axial.lo);
  entry.exit = both.hi;
  entry.exit_cosine = cosine(both.hi, lateral.hi <= axial.hi);
  return entry;
}

double triangle_rectangle_overlap(const double a[2], const double b[2], const double c[2], double x0,
                                  double x1, double y0, double y1) {
  // Sutherland-Hodgman against the four half-planes, then the shoelace area.
  double poly[2][16][2];
  int n = 3;
  for (int k = 0; k < 2; ++k) {
    poly[0][0][k] = a[k];
    poly[0][1][k] = b[k];
    poly[0][2][k] = c[k];
  }
  int cur = 0;
  for (int side = 0; side < 4 && n > 0; ++side) {
    const int axis = side / 2;
    const double bound = side == 0 ? x0 : side == 1 ? x1 : side == 2 ? y0 : y1;
    const double sign = side % 2 == 0 ? 1.0 : -1.0;  // keep sign * (v - bound) >= 0
    const auto& in = poly[cur];
    auto& out = poly[1 - cur];
    int m = 0;
    for (int i = 0; i < n; ++i) {
      const double* p = in[i];
      const double* q = in[(i + 1) % n];
      const double dp = sign * (p[axis] - bound), dq = sign * (q[axis] - bound);
      if (dp >= 0) {
        out[m][0] = p[0];
        out[m][1] = p[1];
        ++m;
      }
      if ((dp >= 0) != (dq >= 0)) {
        const double s = dp / (dp - dq);
        out[m][0] = p[0] + s * (q[0] - p[0]);
        out[m][1] = p[1] + s * (q[1] - p[1]);
        out[m][axis] = bound;
        ++m;
      }
    }
    n = m;
    cur = 1 - cur;
  }
  double twice = 0;
  for (int i = 0; i < n; ++i) {
    const double* p = poly[cur][i];
    const double* q = poly[cur][(i + 1) % n];
    twice += p[0] * q[1] - q[0] * p[1];
  }
  return 0.5 * std::abs(twice);
}

Piece clip_triangle_to_box(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& lo, const Vec3& hi) {
  // Sutherland-Hodgman against the six faces: a triangle keeps at most 9 corners.
  Vec3 buffers[2][12];
  int n = 3;
  buffers[0][0] = a;
  buffers[0][1] = b;
  buffers[0][2] = c;
  int cur = 0;
  for (int side = 0; side < 6 && n > 0; ++side) {
    const int axis = side / 2;
    const double bound = side % 2 ? hi[axis] : lo[axis];
    const double sign = side % 2 ? -1.0 : 1.0;  // keep sign * (v - bound) >= 0
    const Vec3* in = buffers[cur];
    Vec3* out = buffers[1 - cur];
    int m = 0;
    for (int i = 0; i < n; ++i) {
      const Vec3& p = in[i];
      const Vec3& q = in[(i + 1) % n];
      const double dp = sign * (p[axis] - bound), dq = sign * (q[axis] - bound);
      if (dp >= 0) out[m++] = p;
      if ((dp >= 0) != (dq >= 0)) {
        out[m] = p + dp / (dp - dq) * (q - p);
        out[m][axis] = bound;
        ++m;
      }
    }
    n = m;
    cur = 1 - cur;
  }
  Piece piece;
  if (n < 3) return piece;
  const Vec3* poly = buffers[cur];
  Vec3 weighted = Vec3::Zero();
  for (int i = 1; i + 1 < n; ++i) {
    const double area = 0.5 * (poly[i] - poly[0]).cross(poly[i + 1] - poly[0]).norm();
    piece.area += area;
    weighted += area * (poly[0] + poly[i] + poly[i + 1]) / 3;
  }
  piece.centroid = piece.area > 0 ? Vec3(weighted / piece.area) : poly[0];
  return piece;
}

}  // namespace mtcs::thermal::fv
