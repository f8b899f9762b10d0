// The tiled nearest-bore distances skip bores by bounds on their boxes; what they return must be
// the plain loop's over every bore, bit for bit, whatever the bores: near, far, crossing the
// samples, of zero length, diagonal, many or none.

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <random>

#include "eval/surface_samples.h"
#include "eval/tiled_samples.h"
#include "support/plain_nearest_squared.h"

using namespace mtcs;
using geometry::Vec3;

TEST_CASE("tiled nearest squared distances equal the plain loop bit for bit", "[eval][tiles]") {
  // Samples on a box cavity and scattered in the block (no tile shape is assumed).
  const geometry::Box block{{0, 0, 0}, {300, 200, 120}};
  eval::SurfaceSamples samples = eval::sample_box({{40, 30, 50}, {260, 170, 110}}, 4.0);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < 301; ++i)
    samples.x.push_back(300 * u(rng)), samples.y.push_back(200 * u(rng)), samples.z.push_back(120 * u(rng)),
        samples.weight.push_back(1);
  // On the block's faces y = 0 and z = 0, with both signs of zero: exact zero offsets from the
  // axis-parallel segments along them below.
  for (int i = 0; i < 40; ++i)
    samples.x.push_back(7.5 * i), samples.y.push_back(i % 2 ? -0.0 : 0.0), samples.z.push_back(i % 3 ? 0.0 : -0.0),
        samples.weight.push_back(1);
  const Vec3 origin = block.min;
  const eval::TiledSamples tiles(samples, origin);
  REQUIRE(tiles.slots() % eval::TiledSamples::kTile == 0);
  REQUIRE(tiles.slots() >= samples.size());
  auto point = [&] { return Vec3(300 * u(rng), 200 * u(rng), 120 * u(rng)); };
  std::vector<float> m(tiles.slots());
  for (int trial = 0; trial < 60; ++trial) {
    std::vector<eval::FlowSegment> segments;
    const int n = trial % 7 == 0 ? 0 : 1 + int(u(rng) * 12);
    for (int b = 0; b < n; ++b) {
      Vec3 p = point(), q = point();
      const int kind = int(u(rng) * 7);
      if (kind == 0) q = p;                                                  // zero length
      if (kind == 1) q = p, q[int(u(rng) * 3)] += 200 * (u(rng) - 0.5);      // axis-parallel
      if (kind == 2) p += Vec3(500, -400, 900), q += Vec3(500, -400, 900);   // far outside
      if (kind == 3) p.z() = q.z() = 50 + 1e-4 * u(rng);                     // on the cavity's face
      if (kind == 4) {  // axis-parallel through samples: exact zero offsets
        const std::size_t j = std::size_t(u(rng) * double(samples.size()));
        p = Vec3(samples.x[j], samples.y[j], samples.z[j]), q = p;
        q[int(u(rng) * 3)] += 200 * (u(rng) - 0.5);
      }
      if (kind == 5) p = Vec3(300 * u(rng), 0.0, -0.0), q = Vec3(300 * u(rng), -0.0, 0.0);  // signed zeros along x
      segments.push_back({p, q});
    }
    // Near copies: equal distances from several bores.
    if (n > 1) segments.push_back(segments.front());
    tiles.nearest_squared(segments.data(), segments.data() + segments.size(), m.data());
    const auto plain = mtcs_test::plain_nearest_squared(samples, origin, segments);
    INFO("trial " << trial << ", " << segments.size() << " bores");
    int differ = 0;
    for (std::size_t i = 0; i < samples.size(); ++i) differ += m[tiles.slot(i)] != plain[i];
    CHECK(differ == 0);
    // A padded slot repeats a sample: the largest value is the samples'.
    if (n > 0)
      CHECK(*std::max_element(m.begin(), m.end()) == *std::max_element(plain.begin(), plain.end()));
  }
}
