#include "mtcs/mesh/triangle_intersection.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "mtcs/geometry/triangle_distance.h"
#include "mtcs/mesh/exact_predicates.h"

namespace mtcs::mesh {
namespace {

// Projection onto the coordinate plane that drops axis `drop`, keeping orientation handedness
// irrelevant: every 2-D test below accepts both turning directions.
struct Plane2 {
  int u, v;
  double x(const Vec3& p) const { return p[u]; }
  double y(const Vec3& p) const { return p[v]; }
};

Plane2 projection_of(const Triangle& t) {
  const Vec3 n = (t[1] - t[0]).cross(t[2] - t[0]).cwiseAbs();
  int drop = 0;
  n.maxCoeff(&drop);
  return {(drop + 1) % 3, (drop + 2) % 3};
}

int orient(const Plane2& pl, const Vec3& a, const Vec3& b, const Vec3& c) {
  return orient2d(pl.x(a), pl.y(a), pl.x(b), pl.y(b), pl.x(c), pl.y(c));
}

// p on the closed segment ab, given that the three are collinear.
bool within(const Plane2& pl, const Vec3& a, const Vec3& b, const Vec3& p) {
  return std::min(pl.x(a), pl.x(b)) <= pl.x(p) && pl.x(p) <= std::max(pl.x(a), pl.x(b)) &&
         std::min(pl.y(a), pl.y(b)) <= pl.y(p) && pl.y(p) <= std::max(pl.y(a), pl.y(b));
}

bool segments_meet_2d(const Plane2& pl, const Vec3& p1, const Vec3& p2, const Vec3& q1, const Vec3& q2) {
  const int o1 = orient(pl, p1, p2, q1), o2 = orient(pl, p1, p2, q2);
  const int o3 = orient(pl, q1, q2, p1), o4 = orient(pl, q1, q2, p2);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && within(pl, p1, p2, q1)) || (o2 == 0 && within(pl, p1, p2, q2)) ||
         (o3 == 0 && within(pl, q1, q2, p1)) || (o4 == 0 && within(pl, q1, q2, p2));
}

bool inside_2d(const Plane2& pl, const Triangle& t, const Vec3& p) {
  const int o0 = orient(pl, t[0], t[1], p), o1 = orient(pl, t[1], t[2], p), o2 = orient(pl, t[2], t[0], p);
  return (o0 >= 0 && o1 >= 0 && o2 >= 0) || (o0 <= 0 && o1 <= 0 && o2 <= 0);
}

bool coplanar_triangles_meet(const Triangle& a, const Triangle& b) {
  const Plane2 pl = projection_of(a);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      if (segments_meet_2d(pl, a[i], a[(i + 1) % 3], b[j], b[(j + 1) % 3])) return true;
  return inside_2d(pl, b, a[0]) || inside_2d(pl, a, b[0]);
}

bool same_strict_side(const int s[3]) { return (s[0] > 0 && s[1] > 0 && s[2] > 0) || (s[0] < 0 && s[1] < 0 && s[2] < 0); }

enum class Verdict { kApart, kCrossing, kCoplanar };

// The sides of three points of t's plane: orient3d(t[0], t[1], t[2], p[k]). One normal serves
// the three; each sign is taken from it when it clears a bound of 32 eps times the permanent
// (the rounding of this evaluation stays below 8 eps of it, as in Shewchuk's orient3d), else
// from the exact predicate.
void plane_sides(const Triangle& t, const Triangle& p, int s[3]) {
  const Vec3 u = t[1] - t[0], v = t[2] - t[0];
  const Vec3 n = u.cross(v);
  const Vec3 m(std::abs(u.y() * v.z()) + std::abs(u.z() * v.y()), std::abs(u.z() * v.x()) + std::abs(u.x() * v.z()),
               std::abs(u.x() * v.y()) + std::abs(u.y() * v.x()));
  constexpr double kBound = 32 * 0x1p-53;
  for (int k = 0; k < 3; ++k) {
    const Vec3 w = p[k] - t[0];
    const double det = n.dot(w), permanent = m.dot(w.cwiseAbs());
    if (permanent > 1e-200 && std::abs(det) > kBound * permanent) s[k] = det > 0 ? 1 : -1;
    else s[k] = orient3d(t[0], t[1], t[2], p[k]);
  }
}

// Guigue and Devillers ("Fast and robust triangle-triangle overlap test using orientation
// predicates", 2003), after their reference code: with p1 alone on its side of T2's plane and
// p2 alone on its side of T1's plane (orders fixed so both lie on the positive side), the
// segments T1 and T2 cut from the planes' common line overlap iff two orientations say so.
bool overlap_on_line(const Vec3& p1, const Vec3& q1, const Vec3& r1, const Vec3& p2, const Vec3& q2, const Vec3& r2) {
  return orient3d(q1, p2, p1, q2) <= 0 && orient3d(p1, p2, r1, r2) <= 0;
}

// T1 = (p1, q1, r1) permuted so that p1 is alone on its side of T2's plane; s: the sides of
// p2, q2, r2 of T1's plane.
bool gd_second(const Vec3& p1, const Vec3& q1, const Vec3& r1, const Vec3& p2, const Vec3& q2, const Vec3& r2,
               int sp, int sq, int sr, bool* coplanar) {
  if (sp > 0) {
    if (sq > 0) return overlap_on_line(p1, r1, q1, r2, p2, q2);
    if (sr > 0) return overlap_on_line(p1, r1, q1, q2, r2, p2);
    return overlap_on_line(p1, q1, r1, p2, q2, r2);
  }
  if (sp < 0) {
    if (sq < 0) return overlap_on_line(p1, q1, r1, r2, p2, q2);
    if (sr < 0) return overlap_on_line(p1, q1, r1, q2, r2, p2);
    return overlap_on_line(p1, r1, q1, p2, q2, r2);
  }
  if (sq < 0) {
    if (sr >= 0) return overlap_on_line(p1, r1, q1, q2, r2, p2);
    return overlap_on_line(p1, q1, r1, p2, q2, r2);
  }
  if (sq > 0) {
    if (sr > 0) return overlap_on_line(p1, r1, q1, p2, q2, r2);
    return overlap_on_line(p1, q1, r1, q2, r2, p2);
  }
  if (sr > 0) return overlap_on_line(p1, q1, r1, r2, p2, q2);
  if (sr < 0) return overlap_on_line(p1, r1, q1, r2, p2, q2);
  *coplanar = true;
  return false;
}

Verdict classify(const Triangle& a, const Triangle& b) {
  int sb[3], sa[3];
  plane_sides(a, b, sb);
  if (same_strict_side(sb)) return Verdict::kApart;
  plane_sides(b, a, sa);
  if (same_strict_side(sa)) return Verdict::kApart;
  const Vec3 &p1 = a[0], &q1 = a[1], &r1 = a[2], &p2 = b[0], &q2 = b[1], &r2 = b[2];
  const int dp1 = sa[0], dq1 = sa[1], dr1 = sa[2], dp2 = sb[0], dq2 = sb[1], dr2 = sb[2];
  bool coplanar = false;
  bool meet;
  // Bring T1's lone vertex first (and T2 into the matching orientation).
  if (dp1 > 0) {
    if (dq1 > 0) meet = gd_second(r1, p1, q1, p2, r2, q2, dp2, dr2, dq2, &coplanar);
    else if (dr1 > 0) meet = gd_second(q1, r1, p1, p2, r2, q2, dp2, dr2, dq2, &coplanar);
    else meet = gd_second(p1, q1, r1, p2, q2, r2, dp2, dq2, dr2, &coplanar);
  } else if (dp1 < 0) {
    if (dq1 < 0) meet = gd_second(r1, p1, q1, p2, q2, r2, dp2, dq2, dr2, &coplanar);
    else if (dr1 < 0) meet = gd_second(q1, r1, p1, p2, q2, r2, dp2, dq2, dr2, &coplanar);
    else meet = gd_second(p1, q1, r1, p2, r2, q2, dp2, dr2, dq2, &coplanar);
  } else if (dq1 < 0) {
    if (dr1 >= 0) meet = gd_second(q1, r1, p1, p2, r2, q2, dp2, dr2, dq2, &coplanar);
    else meet = gd_second(p1, q1, r1, p2, q2, r2, dp2, dq2, dr2, &coplanar);
  } else if (dq1 > 0) {
    if (dr1 > 0) meet = gd_second(p1, q1, r1, p2, r2, q2, dp2, dr2, dq2, &coplanar);
    else meet = gd_second(q1, r1, p1, p2, q2, r2, dp2, dq2, dr2, &coplanar);
  } else if (dr1 > 0) {
    meet = gd_second(r1, p1, q1, p2, q2, r2, dp2, dq2, dr2, &coplanar);
  } else if (dr1 < 0) {
    meet = gd_second(r1, p1, q1, p2, r2, q2, dp2, dr2, dq2, &coplanar);
  } else {
    coplanar = true;
    meet = false;
  }
  if (coplanar) return coplanar_triangles_meet(a, b) ? Verdict::kCoplanar : Verdict::kApart;
  return meet ? Verdict::kCrossing : Verdict::kApart;
}

// Where triangle t meets the plane through o with normal n (t crosses or touches it): the two
// extreme points of that set along `dir`, from floating-point signed distances.
std::array<Vec3, 2> plane_cut(const Triangle& t, const Vec3& o, const Vec3& n, const Vec3& dir) {
  double d[3];
  for (int k = 0; k < 3; ++k) d[k] = (t[k] - o).dot(n);
  std::vector<Vec3> pts;
  for (int k = 0; k < 3; ++k) {
    const int j = (k + 1) % 3;
    if (d[k] == 0) pts.push_back(t[k]);
    if ((d[k] < 0 && d[j] > 0) || (d[k] > 0 && d[j] < 0)) pts.push_back(t[k] + (t[j] - t[k]) * (d[k] / (d[k] - d[j])));
  }
  if (pts.empty()) {  // rounding put t off the plane it touches: its nearest corner
    int k = 0;
    for (int i = 1; i < 3; ++i)
      if (std::abs(d[i]) < std::abs(d[k])) k = i;
    pts.push_back(t[k]);
  }
  auto by_dir = [&](const Vec3& x, const Vec3& y) { return x.dot(dir) < y.dot(dir); };
  return {*std::min_element(pts.begin(), pts.end(), by_dir), *std::max_element(pts.begin(), pts.end(), by_dir)};
}

// Corners of the common polygon of two coplanar triangles: corners of one inside the other and
// crossings of their edges.
std::array<Vec3, 2> coplanar_extremes(const Triangle& a, const Triangle& b) {
  const Plane2 pl = projection_of(a);
  std::vector<Vec3> pts;
  for (int k = 0; k < 3; ++k) {
    if (inside_2d(pl, b, a[k])) pts.push_back(a[k]);
    if (inside_2d(pl, a, b[k])) pts.push_back(b[k]);
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const Vec3 &p = a[i], &r = a[(i + 1) % 3], &q = b[j], &s = b[(j + 1) % 3];
      const double den = (pl.x(r) - pl.x(p)) * (pl.y(s) - pl.y(q)) - (pl.y(r) - pl.y(p)) * (pl.x(s) - pl.x(q));
      if (den == 0 || !segments_meet_2d(pl, p, r, q, s)) continue;
      const double u = ((pl.x(q) - pl.x(p)) * (pl.y(s) - pl.y(q)) - (pl.y(q) - pl.y(p)) * (pl.x(s) - pl.x(q))) / den;
      pts.push_back(p + (r - p) * std::clamp(u, 0.0, 1.0));
    }
  if (pts.empty()) pts.push_back(a[0]);  // not reached for meeting triangles
  std::array<Vec3, 2> best{pts[0], pts[0]};
  double far = -1;
  for (std::size_t i = 0; i < pts.size(); ++i)
    for (std::size_t j = i; j < pts.size(); ++j)
      if ((pts[i] - pts[j]).squaredNorm() > far) far = (pts[i] - pts[j]).squaredNorm(), best = {pts[i], pts[j]};
  return best;
}

}  // namespace

bool triangles_intersect(const Triangle& a, const Triangle& b) { return classify(a, b) != Verdict::kApart; }

TriangleIntersection intersect_triangles(const Triangle& a, const Triangle& b) {
  TriangleIntersection r;
  const Verdict v = classify(a, b);
  if (v == Verdict::kApart) return r;
  r.intersects = true;
  if (v == Verdict::kCoplanar) {
    r.coplanar = true;
    const auto e = coplanar_extremes(a, b);
    r.p = e[0], r.q = e[1];
    return r;
  }
  const Vec3 na = (a[1] - a[0]).cross(a[2] - a[0]), nb = (b[1] - b[0]).cross(b[2] - b[0]);
  const Vec3 dir = na.cross(nb);
  // The common segment is the overlap of a's cut by b's plane and b's cut by a's plane.
  const auto ca = plane_cut(a, b[0], nb, dir), cb = plane_cut(b, a[0], na, dir);
  r.p = ca[0].dot(dir) > cb[0].dot(dir) ? ca[0] : cb[0];
  r.q = ca[1].dot(dir) < cb[1].dot(dir) ? ca[1] : cb[1];
  if (r.q.dot(dir) < r.p.dot(dir)) r.q = r.p;  // a touching point, rounded apart
  return r;
}

double triangle_distance(const Triangle& a, const Triangle& b) {
  if (triangles_intersect(a, b)) return 0;
  // Apart, the closest points lie on an edge of one of them.
  double best = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    const int j = (k + 1) % 3;
    best = std::min(best, geometry::segment_triangle_distance(a[k], a[j], b[0], b[1], b[2]));
    best = std::min(best, geometry::segment_triangle_distance(b[k], b[j], a[0], a[1], a[2]));
  }
  return best;
}

}  // namespace mtcs::mesh
