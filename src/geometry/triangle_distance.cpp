#include "mtcs/geometry/triangle_distance.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "mtcs/geometry/segment_distance.h"

namespace mtcs::geometry {

Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;  // vertex region a
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;  // vertex region b
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;  // edge ab
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;  // vertex region c
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;  // edge ac
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
    return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);  // edge bc
  const double denom = 1 / (va + vb + vc);
  if (!std::isfinite(denom)) return a;  // degenerate triangle: its edges were handled above
  return a + ab * (vb * denom) + ac * (vc * denom);
}

double segment_triangle_distance(const Vec3& p0, const Vec3& p1, const Vec3& a, const Vec3& b,
                                 const Vec3& c) {
  // Crossing the triangle's interior: the segment's ends on both sides of the plane and the
  // crossing point inside (barycentric test).
  const Vec3 n = (b - a).cross(c - a);
  const double h0 = n.dot(p0 - a), h1 = n.dot(p1 - a);
  if ((h0 <= 0 && h1 >= 0) || (h0 >= 0 && h1 <= 0)) {
    if (h0 != h1) {
      const Vec3 x = p0 + (h0 / (h0 - h1)) * (p1 - p0);
      const double ea = n.dot((b - a).cross(x - a)), eb = n.dot((c - b).cross(x - b)),
                   ec = n.dot((a - c).cross(x - c));
      if (ea >= 0 && eb >= 0 && ec >= 0) return 0;
    }
  }
  // Otherwise an end of the segment, or an edge of the triangle, carries the minimum.
  double d = std::min((p0 - closest_point_on_triangle(p0, a, b, c)).norm(),
                      (p1 - closest_point_on_triangle(p1, a, b, c)).norm());
  const Segment s{p0, p1};
  for (const auto& [u, v] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}})
    d = std::min(d, closest_points(s, {u, v}).distance);
  return d;
}

double segment_box_distance(const Vec3& p0, const Vec3& p1, const Box& box) {
  // f(s) = |p(s) - clamp(p(s))|^2 is a convex piecewise quadratic; its pieces start where a
  // coordinate crosses a slab plane. Minimise each piece in closed form.
  const Vec3 d = p1 - p0;
  std::array<double, 8> breaks{0.0, 1.0};
  int n = 2;
  for (int k = 0; k < 3; ++k) {
    if (d[k] == 0) continue;
    for (const double plane : {box.min[k], box.max[k]}) {
      const double s = (plane - p0[k]) / d[k];
      if (s > 0 && s < 1) breaks[n++] = s;
    }
  }
  for (int i = 1; i < n; ++i)  // insertion sort of at most 8 values
    for (int j = i; j > 0 && breaks[j] < breaks[j - 1]; --j) std::swap(breaks[j], breaks[j - 1]);
  auto excess2 = [&](double s) {
    const Vec3 p = p0 + s * d;
    return (p - p.cwiseMax(box.min).cwiseMin(box.max)).squaredNorm();
  };
  double best = std::min(excess2(0), excess2(1));
  for (int i = 0; i + 1 < n; ++i) {
    const double lo = breaks[i], hi = breaks[i + 1], mid = (lo + hi) / 2;
    // On this piece each coordinate is below, inside or above its slab throughout.
    const Vec3 pm = p0 + mid * d;
    double qa = 0, qb = 0;  // f(s) = qa s^2 + qb s + const
    for (int k = 0; k < 3; ++k) {
      const double bound = pm[k] < box.min[k] ? box.min[k] : (pm[k] > box.max[k] ? box.max[k] : pm[k]);
      if (bound == pm[k]) continue;
      qa += d[k] * d[k];
      qb += 2 * d[k] * (p0[k] - bound);
    }
    if (qa > 0) best = std::min(best, excess2(std::clamp(-qb / (2 * qa), lo, hi)));
  }
  return std::sqrt(best);
}

}  // namespace mtcs::geometry
