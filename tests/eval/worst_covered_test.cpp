// The worst-covered sample (mtcs/eval/worst_covered.h): screened in single precision, re-scored
// in double. The reference is the plain double loop over every sample and bore, first of equals;
// sample and distance must be its own, bit for bit, also where samples tie exactly or differ by
// far less than the screen's rounding, and with the block far from the origin.

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "mtcs/eval/worst_covered.h"
#include "mtcs/geometry/segment_distance.h"

using namespace mtcs;
using geometry::Vec3;

namespace {

eval::WorstSample plain_worst(const std::vector<Vec3>& samples, const mold::Layout& layout) {
  eval::WorstSample worst;
  for (const Vec3& p : samples) {
    double e = std::numeric_limits<double>::infinity();
    for (const auto& b : layout.bores)
      e = std::min(e, geometry::point_segment_distance(p, {b.flow_start, b.flow_end}) - b.diameter / 2);
    if (!worst.any || e > worst.wall_distance) worst = {p, e, true};
  }
  return worst;
}

mold::Bore bore(const Vec3& a, const Vec3& b, double diameter) {
  mold::Bore out;
  out.hole = {a, b, diameter / 2};
  out.flow_start = a, out.flow_end = b, out.diameter = diameter;
  return out;
}

}  // namespace

TEST_CASE("the worst-covered search picks the plain loop's sample and distance", "[eval][reach]") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  const std::vector<Vec3> shifts{Vec3(0, 0, 0), Vec3(1e4, -1e4, 1e4)};
  for (const Vec3& shift : shifts) {
    const geometry::Box block{shift, shift + Vec3(300, 200, 120)};
    auto point = [&]() -> Vec3 { return shift + Vec3(300 * u(rng), 200 * u(rng), 120 * u(rng)); };
    // A cavity's face on a grid (exact ties around axis-parallel bores at grid places) and
    // scattered points.
    std::vector<Vec3> samples;
    for (int x = 50; x <= 250; x += 5)
      for (int y = 25; y <= 175; y += 5) samples.push_back(shift + Vec3(x, y, 105));
    for (int i = 0; i < 200; ++i) samples.push_back(point());
    const eval::WorstCoveredSearch search(samples, block.min);
    for (int trial = 0; trial < 200; ++trial) {
      mold::Layout layout;
      const int n = trial % 17 == 0 ? 0 : 1 + int(u(rng) * 10);
      for (int b = 0; b < n; ++b) {
        const double d = (trial % 3 == 0) ? 8.0 : std::vector<double>{6, 8, 10}[std::size_t(u(rng) * 3)];
        Vec3 p = point(), q = point();
        const int kind = int(u(rng) * 4);
        if (kind == 0) {  // axis-parallel at a grid place: exact ties
          p = shift + Vec3(std::round(p.x() - shift.x()), std::round((p.y() - shift.y()) / 5) * 5, 95);
          q = p, q.x() = shift.x() + 300 * u(rng);
        }
        if (kind == 1) q = p;  // zero length
        layout.bores.push_back(bore(p, q, d));
      }
      const eval::WorstSample want = plain_worst(samples, layout);
      const eval::WorstSample got = search.find(layout);
      REQUIRE(got.any);
      CHECK(got.point == want.point);
      CHECK(got.wall_distance == want.wall_distance);  // bit for bit
      // Asked again (the search keeps its answers by the bores' geometry), and with one bore's
      // diameter or end changed, which must not find the kept answer.
      CHECK(search.find(layout).wall_distance == want.wall_distance);
      if (n > 0) {
        mold::Layout other = layout;
        if (trial % 2 == 0) other.bores.back().diameter += 2;
        else other.bores.back().flow_end.z() += 1e-9;
        const eval::WorstSample changed = search.find(other), plain = plain_worst(samples, other);
        CHECK(changed.point == plain.point);
        CHECK(changed.wall_distance == plain.wall_distance);
      }
    }
  }
  CHECK_FALSE(eval::WorstCoveredSearch({}, Vec3::Zero()).find(mold::Layout{}).any);
}

TEST_CASE("the worst-covered search resolves samples closer than its screen's rounding", "[eval][reach]") {
  // Samples on a circle around a bore's axis whose radii differ by 1e-9 mm (the screen rounds
  // to ~1e-5): only the double re-score can tell which is farthest; in the order given, the
  // farthest (radius 30 + 3e-9, twice) is neither first nor last.
  const Vec3 origin(-20, -20, -20);
  mold::Layout layout;
  layout.bores.push_back(bore({0, 0, -100}, {0, 0, 100}, 8));
  std::vector<Vec3> samples;
  const double radii[] = {30, 30 + 1e-9, 30 + 3e-9, 30 + 2e-9, 30 + 3e-9, 30 - 1e-9};
  for (int i = 0; i < 6; ++i) {
    const double a = 0.7 * i;
    samples.emplace_back(radii[i] * std::cos(a), radii[i] * std::sin(a), 0.1 * i);
  }
  const eval::WorstCoveredSearch search(samples, origin);
  const eval::WorstSample got = search.find(layout), want = plain_worst(samples, layout);
  CHECK(got.point == want.point);
  CHECK((want.point == samples[2] || want.point == samples[4]));
  CHECK(got.wall_distance == want.wall_distance);
}
