// Upper-bounded distance between solid cylinders: Biermann, Joliet, Michelitsch, Algorithm 1.
//
// Deviations from the paper (docs/distance-kernel.md has the reasoning):
//  * The four circle-disk, four circle-shell and four circle-circle computations are merged into
//    four rim-versus-solid minimisations: along each rim we minimise the closed-form SIGNED
//    distance to the other solid. Its minimum is the rim's distance to the solid when positive
//    and a penetration depth when negative, so "a rim enters the other solid" and "how far" come
//    out of the same search. Shell-disk and disk-disk minima always extend to a rim (they are
//    attained on a segment or a patch), so shell-shell plus the four rims are complete.
//  * The pretest for disk-disk intersection is subsumed: two intersecting disks put a rim point
//    inside the other solid.
//  * Pairs that end up within 1e-10 S of contact are recomputed in 113-bit arithmetic, so that
//    touching pairs are reported as intersecting and pairs 1e-16 apart as separated.

#include "mtcs/geometry/cylinder_distance.h"

#include <array>
#include <tuple>

#include "detail/circle_minimize.h"
#include "detail/cylinder_frame.h"
#include "detail/segment_segment.h"

namespace mtcs::geometry {
namespace {

using detail::CylFrame;
using detail::quad;
using detail::V3;

template <class R>
struct Outcome {
  R value;  // distance when >= 0, minus the penetration depth when < 0
  Feature feature;
  bool bounded;
  V3<R> wa, wb;
};

// Depth of point p inside the solid cylinder (base c0, axis cd, radius r); negative outside.
template <class R>
R end_inside_depth(const V3<R>& p, const V3<R>& c0, const V3<R>& cd, R r) {
  const V3<R> y = p - c0;
  const R len2 = detail::norm2(cd), ty = dot(y, cd);
  if (ty < R(0) || ty > len2 || len2 == R(0)) return R(-1);
  const R rho2 = detail::norm2(y) - ty * ty / len2;
  if (rho2 > r * r) return R(-1);
  const R len = detail::sqrt_(len2), t = ty / len;
  return detail::min_(r - detail::sqrt_(detail::max_(R(0), rho2)), detail::min_(t, len - t));
}

// Depth by which the axis of `s` passes through the disk (centre c, unit normal n, radius r):
// the smallest of the margins that make the crossing true; negative when it does not cross.
template <class R>
R axis_crossing_depth(const CylFrame<R>& s, const V3<R>& c, const V3<R>& n, R r, V3<R>* at) {
  const R h0 = dot(s.p0 - c, n), h1 = dot(s.p1() - c, n);
  if ((h0 > R(0) && h1 > R(0)) || (h0 < R(0) && h1 < R(0)) || h0 == h1) return R(-1);
  *at = s.p0 + (h0 / (h0 - h1)) * s.d;
  const V3<R> off = *at - c;
  const R rho = norm(off - dot(off, n) * n);
  return detail::min_(r - rho, detail::min_(detail::abs_(h0), detail::abs_(h1)));
}

template <class R>
bool axes_parallel(const CylFrame<R>& a, const CylFrame<R>& b) {
  return detail::norm2(detail::cross(a.w, b.w)) <= R(1e-24);
}

// Tolerance and contact threshold, relative to max(1, S); S is computed only by the pairs that
// get past the pretests.
template <class R>
struct Thresholds {
  R tolerance;  // absolute error target of the numerical parts, / max(1, S)
  R contact;    // a penetration deeper than this * max(1, S) is a final verdict
};

template <class R>
R scale_of(const V3<R>& a0, const V3<R>& da, R ra, const V3<R>& b0, const V3<R>& db, R rb) {
  const V3<R> mid = (b0 + db * R(0.5)) - (a0 + da * R(0.5));
  return detail::max_(R(1), detail::max_(detail::max_(norm(da), norm(db)),
                                         detail::max_(detail::max_(ra, rb), norm(mid))));
}

template <class R>
Outcome<R> solve(const V3<R>& a0, const V3<R>& da, R ra, const V3<R>& b0, const V3<R>& db, R rb,
                 R upper, const Thresholds<R>& th, bool pretests, bool sorted) {
  const R inf = detail::Limits<R>::infinity();
  Outcome<R> best{inf, Feature::Bounded, true, {}, {}};

  // 1. Axis segments: the capsule lower bound, and the exact answer when both closest points
  //    are interior (the shells' common normal then joins the axes).
  const auto ss = detail::segment_segment(a0, da, b0, db);
  const R dls = detail::sqrt_(ss.dist2);
  const R lower = dls - ra - rb;
  if (ss.interior) {
    V3<R> n = ss.pb - ss.pa;
    if (dls > R(0)) {
      n = n * (R(1) / dls);
    } else {
      V3<R> w = da * (R(1) / norm(da)), v;
      detail::orthonormal_basis(w, &n, &v);
    }
    if (lower > R(0)) {
      best = {lower, Feature::ShellShell, false, ss.pa + ra * n, ss.pb - rb * n};
    } else {
      // A common point: on the common perpendicular, within ra of one axis and rb of the other.
      const V3<R> x = ss.pa + detail::max_(R(0), dls - rb) * n;
      best = {lower, Feature::Intersecting, false, x, x};
    }
    if (pretests) return best;
  }
  if (pretests && lower >= upper) return {lower, Feature::Bounded, true, {}, {}};

  const R s1 = scale_of(a0, da, ra, b0, db, rb);
  const R tol = th.tolerance * s1, contact = th.contact * s1;

  // 2. Interpenetration, possible only where the capsules overlap: an axis end inside the
  //    other solid (bores meeting at a junction), then an axis through the other's end disk
  //    (crossing bores that no rim or shell test sees).
  if (lower <= R(0)) {
    for (const auto& [p, c0, cd, cr] : {std::tuple{a0, b0, db, rb}, std::tuple{a0 + da, b0, db, rb},
                                        std::tuple{b0, a0, da, ra}, std::tuple{b0 + db, a0, da, ra}}) {
      const R depth = end_inside_depth(p, c0, cd, cr);
      if (depth >= R(0) && -depth < best.value) {
        best = {-depth, Feature::Intersecting, false, p, p};
        if (depth > contact) return best;
      }
    }
  }
  const auto a = detail::make_frame<R>(a0, da, ra);
  const auto b = detail::make_frame<R>(b0, db, rb);
  if (lower <= R(0)) {
    R deepest = R(-1);
    V3<R> at{}, where{};
    const CylFrame<R>* cyl[2] = {&a, &b};
    for (int i = 0; i < 2; ++i) {
      const CylFrame<R>& s = *cyl[i];
      const CylFrame<R>& o = *cyl[1 - i];
      for (const V3<R>& c : {o.p0, o.p1()}) {
        const R depth = axis_crossing_depth(s, c, o.w, o.r, &at);
        if (depth > deepest) deepest = depth, where = at;
      }
    }
    if (deepest >= R(0) && -deepest < best.value) {
      best = {-deepest, Feature::Intersecting, false, where, where};
      if (deepest > contact) return best;
    }
  }

  // 3. The four rims against the other solid, in order of their lower bounds.
  struct Rim {
    const CylFrame<R>* owner;
    const CylFrame<R>* other;
    V3<R> center;
    R lower;
  };
  std::array<Rim, 4> rims{{{&a, &b, a.p0, R(0)},
                           {&a, &b, a.p1(), R(0)},
                           {&b, &a, b.p0, R(0)},
                           {&b, &a, b.p1(), R(0)}}};
  for (Rim& rim : rims) {
    R t;
    const R d2 = detail::point_segment_dist2(rim.center, rim.other->p0, rim.other->d, &t);
    rim.lower = detail::max_(lower, detail::sqrt_(d2) - rim.owner->r - rim.other->r);
  }
  if (sorted) {
    // Insertion sort: four items, no allocation.
    for (int i = 1; i < 4; ++i)
      for (int j = i; j > 0 && rims[j].lower < rims[j - 1].lower; --j) std::swap(rims[j], rims[j - 1]);
  }
  R bound = detail::min_(upper, best.value);
  for (const Rim& rim : rims) {
    if (sorted && rim.lower >= bound) break;
    const CylFrame<R>& own = *rim.owner;
    const CylFrame<R>& oth = *rim.other;
    const detail::CircleInFrame<R> circle(rim.center, own.r, own.u, own.v, oth);
    const detail::RimToSolid<R> f{circle, oth.len, oth.r};
    const auto m = detail::minimize_on_circle<R>(f, own.r, bound, -contact, tol);
    if (!(m.value < bound)) continue;
    bound = m.value;
    const V3<R> x = rim.center + own.r * (m.cos_t * own.u + m.sin_t * own.v);
    detail::Region region;
    const V3<R> y = detail::closest_point_on_solid(oth, x, &region);
    Feature feature = Feature::ShellRim;
    if (m.value <= R(0) || region == detail::Region::Inside) feature = Feature::Intersecting;
    else if (region == detail::Region::Disk) feature = axes_parallel(a, b) ? Feature::DiskDisk : Feature::RimDisk;
    else if (region == detail::Region::Rim) feature = Feature::RimRim;
    best = rim.owner == &a ? Outcome<R>{m.value, feature, false, x, y}
                           : Outcome<R>{m.value, feature, false, y, x};
    if (feature == Feature::Intersecting) best.wa = best.wb = x;
    if (m.value < -contact) break;
  }
  if (!(best.value < upper) && !(best.value <= R(0))) {
    return {detail::max_(upper, lower), Feature::Bounded, true, {}, {}};
  }
  return best;
}

template <class R>
Outcome<R> solve_pair(const Cylinder& ca, const Cylinder& cb, const DistanceRequest& q,
                      const Thresholds<R>& th, V3<R>* origin) {
  // Work relative to the first axis' start: exact by Sterbenz for nearby points far from the
  // origin of the input coordinates.
  *origin = detail::from_eigen<R>(ca.p0);
  const V3<R> a1 = detail::from_eigen<R>(ca.p1);
  const V3<R> b0 = detail::from_eigen<R>(cb.p0), b1 = detail::from_eigen<R>(cb.p1);
  return solve<R>(V3<R>{R(0), R(0), R(0)}, a1 - *origin, R(ca.radius), b0 - *origin, b1 - b0,
                  R(cb.radius), R(q.upper_bound), th, q.pretests, q.sorted_bounds);
}

template <class R>
DistanceResult to_result(const Outcome<R>& o, const V3<R>& origin, R touch) {
  DistanceResult r;
  r.bounded = o.bounded;
  if (!o.bounded && o.value <= touch) {
    r.distance = 0;
    r.feature = Feature::Intersecting;
  } else {
    r.distance = double(o.value);
    r.feature = o.feature;
    if (!(r.distance > 0)) r.distance = std::numeric_limits<double>::denorm_min();
  }
  if (!o.bounded) {
    r.witness_a = detail::to_eigen(o.wa + origin);
    r.witness_b = detail::to_eigen(o.wb + origin);
  }
  return r;
}

}  // namespace

std::string_view to_string(Feature f) {
  switch (f) {
    case Feature::ShellShell: return "shell-shell";
    case Feature::ShellRim: return "shell-rim";
    case Feature::RimDisk: return "rim-disk";
    case Feature::RimRim: return "rim-rim";
    case Feature::DiskDisk: return "disk-disk";
    case Feature::Intersecting: return "intersecting";
    case Feature::Bounded: return "bounded";
  }
  return "unknown";
}

DistanceResult distance(const Cylinder& a, const Cylinder& b, const DistanceRequest& request) {
  if (!is_valid(a) || !is_valid(b)) {
    DistanceResult r;
    r.distance = std::numeric_limits<double>::quiet_NaN();
    return r;
  }
  // Near contact the double result decides nothing: within kMarginal S it is recomputed in
  // quad. The double kernel's error is below 1e-13 S on every certified case and below about
  // eps^(2/3) S ~ 4e-11 S in theory (near-parallel axes), so the band is safely wider.
  constexpr double kMarginal = 1e-10;
  V3<double> origin;
  const auto o = solve_pair<double>(a, b, request, {request.tolerance, kMarginal}, &origin);
  // |x|_1 bounds every norm in S from above: the square roots are paid only near contact.
  const double crude = 1 + (a.p1 - a.p0).lpNorm<1>() + (b.p1 - b.p0).lpNorm<1>() + a.radius +
                       b.radius + (b.p0 + b.p1 - a.p0 - a.p1).lpNorm<1>();
  const bool marginal = request.exact_verdict && !o.bounded && std::abs(o.value) < kMarginal * crude &&
                        std::abs(o.value) < kMarginal * std::max(1.0, pair_scale(a, b));
  if (!marginal) return to_result<double>(o, origin, 0.0);

  V3<quad> qorigin;
  const auto oq = solve_pair<quad>(a, b, request, {quad(1e-26), quad(1e-22)}, &qorigin);
  const quad qs = quad(std::max(1.0, pair_scale(a, b)));
  auto r = to_result<quad>(oq, qorigin, quad(1e-24) * qs);
  r.extended_precision = true;
  return r;
}

}  // namespace mtcs::geometry
