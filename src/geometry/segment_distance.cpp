#include "mtcs/geometry/segment_distance.h"

#include "detail/segment_segment.h"

namespace mtcs::geometry {

double point_segment_distance(const Vec3& p, const Segment& s, double* t) {
  using detail::from_eigen;
  double tt;
  const double d2 = detail::point_segment_dist2(from_eigen<double>(p), from_eigen<double>(s.p0),
                                                from_eigen<double>(s.p1) - from_eigen<double>(s.p0), &tt);
  if (t) *t = tt;
  return std::sqrt(d2);
}

SegmentClosest closest_points(const Segment& a, const Segment& b) {
  using detail::from_eigen;
  // Relative to a.p0, for the same reason as the cylinder kernel.
  const auto o = from_eigen<double>(a.p0);
  const auto r = detail::segment_segment(from_eigen<double>(a.p0) - o,
                                         from_eigen<double>(a.p1) - from_eigen<double>(a.p0),
                                         from_eigen<double>(b.p0) - o,
                                         from_eigen<double>(b.p1) - from_eigen<double>(b.p0));
  return {std::sqrt(r.dist2), r.s, r.t, detail::to_eigen(r.pa + o), detail::to_eigen(r.pb + o), r.interior};
}

}  // namespace mtcs::geometry
