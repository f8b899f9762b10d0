#pragma once
// The wall-distance stage's plain loop, as it was before the tiles (src/eval/tiled_samples.h): per
// sample, the least squared distance to the segments, in the stage's single-precision expressions.
// The tiles and the stage are checked against it bit for bit.

#include <limits>
#include <vector>

#include "eval/surface_samples.h"
#include "eval/tiled_samples.h"

namespace mtcs_test {

inline std::vector<float> plain_nearest_squared(const mtcs::eval::SurfaceSamples& s, const mtcs::geometry::Vec3& origin,
                                                const std::vector<mtcs::eval::FlowSegment>& segments) {
  std::vector<float> m(s.size(), std::numeric_limits<float>::infinity());
  for (const auto& g : segments) {
    const mtcs::geometry::Vec3 a = g.start - origin, d = g.end - g.start;
    const float ax = float(a.x()), ay = float(a.y()), az = float(a.z());
    const float dx = float(d.x()), dy = float(d.y()), dz = float(d.z());
    const float dd = dx * dx + dy * dy + dz * dz, inv = dd > 0 ? 1 / dd : 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const float px = float(s.x[i] - origin.x()) - ax, py = float(s.y[i] - origin.y()) - ay,
                  pz = float(s.z[i] - origin.z()) - az;
      float t = (px * dx + py * dy + pz * dz) * inv;
      t = t < 0.f ? 0.f : (t > 1.f ? 1.f : t);
      const float qx = px - t * dx, qy = py - t * dy, qz = pz - t * dz;
      const float d2 = qx * qx + qy * qy + qz * qz;
      m[i] = d2 < m[i] ? d2 : m[i];
    }
  }
  return m;
}

}  // namespace mtcs_test
