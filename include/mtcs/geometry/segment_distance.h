#pragma once
// Closest points between line segments; robust for parallel, collinear, near-parallel and
// zero-length segments (see src/geometry/detail/segment_segment.h for the method).

#include "mtcs/geometry/primitives.h"

namespace mtcs::geometry {

struct SegmentClosest {
  double distance;
  double s;  // parameter on the first segment, p0 + s (p1 - p0), s in [0, 1]
  double t;  // parameter on the second segment
  Vec3 point_a;
  Vec3 point_b;
  bool interior;  // both closest points lie strictly inside their segments
};

// Distance from a point to a segment; `t` receives the closest parameter in [0, 1].
double point_segment_distance(const Vec3& p, const Segment& s, double* t = nullptr);

SegmentClosest closest_points(const Segment& a, const Segment& b);

}  // namespace mtcs::geometry
