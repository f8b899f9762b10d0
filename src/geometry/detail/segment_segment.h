#pragma once
// Closest points of two segments p0 + s d1 and q0 + t d2, s, t in [0, 1].
//
// The minimiser of a convex quadratic over the unit square is either its interior critical
// point or lies on an edge, i.e. involves an endpoint of one segment. We therefore take the
// minimum over (a) the four endpoint-to-segment distances, which are exact and well-conditioned,
// and (b) the interior critical point, computed in the frame of the second axis (its location
// is ill-conditioned for near-parallel axes, its value is not) and evaluated as a real point
// pair, so that it can never under-estimate. Parallel axes (sine below 1e-10) take the middle
// of the overlap, so that overlapping parallel bores report an interior (shell-shell) pair.

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

template <class R>
SegSeg<R> segment_segment(const V3<R>& p0, const V3<R>& d1, const V3<R>& q0, const V3<R>& d2) {
  SegSeg<R> best;
  auto consider = [&](R s, R t, bool interior) {
    const V3<R> pa = p0 + s * d1, pb = q0 + t * d2;
    const R d2_ = norm2(pa - pb);
    if (d2_ < best.dist2 || (interior && !best.interior && d2_ <= best.dist2)) {
      best = {d2_, s, t, pa, pb, interior};
    }
  };
  best.dist2 = Limits<R>::max();
  best.interior = false;
  R t;
  // Endpoints of the first segment against the second, then the reverse.
  point_segment_dist2(p0, q0, d2, &t), consider(R(0), t, false);
  point_segment_dist2(p0 + d1, q0, d2, &t), consider(R(1), t, false);
  point_segment_dist2(q0, p0, d1, &t), consider(t, R(0), false);
  point_segment_dist2(q0 + d2, p0, d1, &t), consider(t, R(1), false);

  const R a = norm2(d1), c = norm2(d2);
  if (a == R(0) || c == R(0)) return best;
  // Frame of the second axis: w unit, perpendicular parts of the first segment.
  const R lc = sqrt_(c);
  const V3<R> w = d2 * (R(1) / lc);
  const V3<R> r0 = p0 - q0;
  const R t0 = dot(r0, w), dt = dot(d1, w);
  const V3<R> r0p = r0 - t0 * w, d1p = d1 - dt * w;
  const R dp2 = norm2(d1p);
  R s;
  if (dp2 <= R(1e-20) * a) {
    // Parallel: the middle of the overlap of [t0, t0 + dt] and [0, lc], if any.
    const R lo = max_(min_(t0, t0 + dt), R(0)), hi = min_(max_(t0, t0 + dt), lc);
    if (!(lo < hi) || dt == R(0)) return best;
    s = ((lo + hi) / R(2) - t0) / dt;
  } else {
    s = -dot(r0p, d1p) / dp2;
  }
  if (!(s > R(0) && s < R(1))) return best;
  const R tc = (t0 + s * dt) / lc;
  if (!(tc > R(0) && tc < R(1))) return best;
  consider(s, tc, true);
  return best;
}

}  // namespace mtcs::geometry::detail
