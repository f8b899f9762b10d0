#include "mtcs/mesh/wall_thickness.h"

#include <algorithm>

namespace mtcs::mesh {

namespace {
// The ball may cut the surface by 1 % of its radius: a faceted curve (a sphere's 96 facets
// round) would otherwise stop it at the first facet edge, at 2/3 of the diameter.
constexpr double kFits = 1 - 1e-2;
constexpr int kBisections = 14;     // 2^-14 ~ 6e-5 of the bound
}  // namespace

double inscribed_diameter(const TriangleBvh& part, const geometry::Vec3& p, const geometry::Vec3& outward, double cap) {
  // From a hair inside, so p's own triangle is not the first crossing.
  const double start = 1e-6 * (1 + part.bounds().size().norm());
  const auto hit = part.first_hit(p - start * outward, -outward);
  if (!hit) return 0;
  double hi = std::min(0.5 * (hit->t + start), 0.5 * cap);
  const auto fits = [&](double r) {
    const geometry::Vec3 c = p - r * outward;
    return part.segment_distance(c, c, r) >= kFits * r;
  };
  if (fits(hi)) return 2 * hi;  // a flat wall: straight across
  double lo = 0;
  for (int i = 0; i < kBisections; ++i) {
    const double mid = 0.5 * (lo + hi);
    (fits(mid) ? lo : hi) = mid;
  }
  return 2 * (lo > 0 ? lo : hi);  // no radius fitted: thinner than the last tried, never 0
}

}  // namespace mtcs::mesh
