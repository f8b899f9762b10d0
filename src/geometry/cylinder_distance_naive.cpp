// Baseline: every sub-distance of the two surfaces, no pretest, no ordering, no upper bound.
// Slow by design; it is also an independent second method for the tests (it shares only the
// circle minimiser and the segment distance with the fast kernel).

#include <algorithm>

#include "detail/circle_minimize.h"
#include "detail/cylinder_frame.h"
#include "detail/segment_segment.h"
#include "mtcs/geometry/cylinder_distance.h"

namespace mtcs::geometry {
namespace {

using detail::CylFrame;
using V = detail::V3<double>;

// Signed distance from a point to a solid: negative inside.
double point_signed(const CylFrame<double>& c, const V& x) {
  const V y = x - c.p0;
  const double t = detail::dot(y, c.w);
  return detail::solid_signed_distance(t, detail::norm(y - t * c.w), c.len, c.r);
}

// Axis of s passes through a disk of o.
bool axis_through_disk(const CylFrame<double>& s, const CylFrame<double>& o) {
  for (const V& c : {o.p0, o.p1()}) {
    const double h0 = detail::dot(s.p0 - c, o.w), h1 = detail::dot(s.p1() - c, o.w);
    if (h0 * h1 > 0 || h0 == h1) continue;
    const V x = s.p0 + (h0 / (h0 - h1)) * s.d - c;
    if (detail::norm(x - detail::dot(x, o.w) * o.w) <= o.r) return true;
  }
  return false;
}

}  // namespace

DistanceResult distance_naive(const Cylinder& ca, const Cylinder& cb, double tolerance) {
  const double tol = tolerance * std::max(1.0, pair_scale(ca, cb));
  const V o = detail::from_eigen<double>(ca.p0);
  const auto a = detail::make_frame<double>(detail::from_eigen<double>(ca.p0) - o,
                                            detail::from_eigen<double>(ca.p1) - detail::from_eigen<double>(ca.p0), ca.radius);
  const auto b = detail::make_frame<double>(detail::from_eigen<double>(cb.p0) - o,
                                            detail::from_eigen<double>(cb.p1) - detail::from_eigen<double>(cb.p0), cb.radius);
  DistanceResult r;
  const double inf = std::numeric_limits<double>::infinity();
  double best = inf;
  Feature feature = Feature::Bounded;

  // Shell-shell.
  const auto ss = detail::segment_segment(a.p0, a.d, b.p0, b.d);
  if (ss.interior) best = detail::sqrt_(ss.dist2) - a.r - b.r, feature = Feature::ShellShell;

  // Each rim against the other's shell, both disks and (for the rims of a) both rims.
  const CylFrame<double>* cyl[2] = {&a, &b};
  for (int i = 0; i < 2; ++i) {
    const CylFrame<double>& own = *cyl[i];
    const CylFrame<double>& oth = *cyl[1 - i];
    for (const V& center : {own.p0, own.p1()}) {
      const detail::CircleInFrame<double> c(center, own.r, own.u, own.v, oth);
      auto run = [&](auto&& f, Feature kind) {
        const double d = detail::minimize_on_circle<double>(f, own.r, inf, -inf, tol).value;
        if (d < best) best = d, feature = kind;
      };
      run([&](double co, double si) {  // circle-shell
            const double t = c.axial(co, si);
            const double dt = t < 0 ? -t : (t > oth.len ? t - oth.len : 0.0);
            const double dr = c.radial(co, si) - oth.r;
            return detail::sqrt_(dt * dt + dr * dr);
          },
          Feature::ShellRim);
      for (const double end : {0.0, oth.len}) {
        run([&](double co, double si) {  // circle-disk
              const double dt = c.axial(co, si) - end;
              const double dr = std::max(0.0, c.radial(co, si) - oth.r);
              return detail::sqrt_(dt * dt + dr * dr);
            },
            Feature::RimDisk);
        if (i == 0) {
          run([&](double co, double si) {  // circle-circle
                const double dt = c.axial(co, si) - end;
                const double dr = c.radial(co, si) - oth.r;
                return detail::sqrt_(dt * dt + dr * dr);
              },
              Feature::RimRim);
        }
      }
    }
  }
  // An axis end inside the other solid: nesting, or a bore ending inside the other.
  const bool nested = point_signed(a, b.p0) <= 0 || point_signed(a, b.p1()) <= 0 ||
                      point_signed(b, a.p0) <= 0 || point_signed(b, a.p1()) <= 0;
  if (best <= 0 || nested || axis_through_disk(a, b) || axis_through_disk(b, a)) {
    r.distance = 0;
    r.feature = Feature::Intersecting;
  } else {
    r.distance = best;
    r.feature = feature;
  }
  return r;
}

}  // namespace mtcs::geometry
