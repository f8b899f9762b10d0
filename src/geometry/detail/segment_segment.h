#pragma once
// Closest points of two segments p0 + s d1 and q0 + t d2, s, t in [0, 1].
//
// The minimiser of a convex quadratic over the unit square is either its interior critical
// point or lies on an edge, i.e. involves an endpoint of one segment. Near-parallel axes take
// (a) the interior critical point, computed in the frame of the second axis (its location is
// ill-conditioned, its value is not) and evaluated as a real point pair, so that it can never
// under-estimate; failing that (b) the minimum of the four endpoint-to-segment distances.
// Axes parallel to machine precision take the middle of their overlap, so that overlapping
// parallel bores report an interior (shell-shell) pair.

#include "real.h"

namespace mtcs::geometry::detail {

template <class R>
struct SegSeg {
  R dist2;
  R s, t;
  V3<R> pa, pb;
  bool interior;
};

// Squared distance from p to segment q0 + t d, with the parameter.
template <class R>
R point_segment_dist2(const V3<R>& p, const V3<R>& q0, const V3<R>& d, R* t_out) {
  const R dd = norm2(d);
  R t = R(0);
  if (dd > R(0)) t = clamp01(dot(p - q0, d) / dd);
  *t_out = t;
  return norm2(p - (q0 + t * d));
}

// The careful path: near-parallel or degenerate axes. When the interior critical point is
// inside the box it is the minimum and the endpoint candidates are skipped.
template <class R>
SegSeg<R> segment_segment_robust(const V3<R>& p0, const V3<R>& d1, const V3<R>& q0, const V3<R>& d2) {
  const R a = norm2(d1), c = norm2(d2);
  if (a > R(0) && c > R(0)) {
    // Parts of the first segment along and across the second axis (d2 unnormalised).
    const R inv_c = R(1) / c;
    const V3<R> r0 = p0 - q0;
    const R t0 = dot(r0, d2) * inv_c, dt = dot(d1, d2) * inv_c;  // in units of the second axis
    const V3<R> r0p = r0 - t0 * d2, d1p = d1 - dt * d2;
    const R dp2 = norm2(d1p);
    R s = R(-1);
    if (dp2 <= Limits<R>::epsilon() * Limits<R>::epsilon() * a) {
      // Parallel: the middle of the overlap of [t0, t0 + dt] and [0, 1], if any.
      const R lo = max_(min_(t0, t0 + dt), R(0)), hi = min_(max_(t0, t0 + dt), R(1));
      if (lo < hi && dt != R(0)) s = ((lo + hi) / R(2) - t0) / dt;
    } else {
      s = -dot(r0p, d1p) / dp2;
    }
    if (s > R(0) && s < R(1)) {
      const R tc = t0 + s * dt;
      if (tc > R(0) && tc < R(1)) {
        const V3<R> pa = p0 + s * d1, pb = q0 + tc * d2;
        return {norm2(pa - pb), s, tc, pa, pb, true};
      }
    }
  }
  SegSeg<R> best;
  best.dist2 = Limits<R>::max();
  best.interior = false;
  auto consider = [&](R s, R t) {
    const V3<R> pa = p0 + s * d1, pb = q0 + t * d2;
    const R d2_ = norm2(pa - pb);
    if (d2_ < best.dist2) best = {d2_, s, t, pa, pb, false};
  };
  R t;
  // Endpoints of the first segment against the second, then the reverse.
  point_segment_dist2(p0, q0, d2, &t), consider(R(0), t);
  point_segment_dist2(p0 + d1, q0, d2, &t), consider(R(1), t);
  point_segment_dist2(q0, p0, d1, &t), consider(t, R(0));
  point_segment_dist2(q0 + d2, p0, d1, &t), consider(t, R(1));
  return best;
}

// Well-conditioned axes (sine of the angle above 1e-3) take Ericson's clamping sequence
// (Real-Time Collision Detection, 5.1.9), exact for the box-constrained quadratic; the
// determinant is |d1 x d2|^2 rather than the cancelling a c - b^2.
template <class R>
SegSeg<R> segment_segment(const V3<R>& p0, const V3<R>& d1, const V3<R>& q0, const V3<R>& d2) {
  const R a = norm2(d1), e = norm2(d2);
  const R det = norm2(cross(d1, d2));
  if (!(det > R(1e-6) * a * e)) return segment_segment_robust(p0, d1, q0, d2);
  const V3<R> r = p0 - q0;
  const R b = dot(d1, d2), c = dot(d1, r), f = dot(d2, r);
  R s = (b * f - c * e) / det;
  bool interior = s > R(0) && s < R(1);
  s = clamp01(s);
  R t = (b * s + f) / e;
  if (t <= R(0)) {
    t = R(0), s = clamp01(-c / a), interior = false;
  } else if (t >= R(1)) {
    t = R(1), s = clamp01((b - c) / a), interior = false;
  }
  const V3<R> pa = p0 + s * d1, pb = q0 + t * d2;
  return {norm2(pa - pb), s, t, pa, pb, interior};
}

}  // namespace mtcs::geometry::detail
