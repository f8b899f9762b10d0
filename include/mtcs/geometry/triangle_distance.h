#pragma once
// Point-triangle and segment-triangle distances, and the axis-aligned box primitives the mold
// scene needs (segment-box distance, ray-box exit).

#include <limits>

#include "mtcs/geometry/primitives.h"

namespace mtcs::geometry {

struct Box {
  Vec3 min;
  Vec3 max;

  // The box that contains nothing: growing it by points or boxes gives their bounds.
  static Box empty() {
    return {Vec3::Constant(std::numeric_limits<double>::infinity()), Vec3::Constant(-std::numeric_limits<double>::infinity())};
  }
  Vec3 size() const { return max - min; }
  bool contains(const Vec3& p) const {
    return (p.array() >= min.array()).all() && (p.array() <= max.array()).all();
  }
};

// Squared distance between two boxes (0 when they touch or overlap).
inline double box_distance_sq(const Box& a, const Box& b) {
  return (a.min - b.max).cwiseMax(b.min - a.max).cwiseMax(0.0).squaredNorm();
}

// Closest point of triangle (a, b, c) to p (Ericson, Real-Time Collision Detection 5.1.5).
Vec3 closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c);

// Distance between the segment p0 -> p1 and the filled triangle (a, b, c); 0 when they meet.
double segment_triangle_distance(const Vec3& p0, const Vec3& p1, const Vec3& a, const Vec3& b,
                                 const Vec3& c);

// Distance between the segment p0 -> p1 and the solid box; 0 when the segment touches it.
double segment_box_distance(const Vec3& p0, const Vec3& p1, const Box& box);

}  // namespace mtcs::geometry
