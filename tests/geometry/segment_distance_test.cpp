// Segment-segment distance: degenerate and parallel configurations with closed forms, and random
// pairs against a golden-section oracle (the distance is convex in s for the exact t(s)).

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "mtcs/geometry/segment_distance.h"
#include "support/random_draws.h"

using namespace mtcs::geometry;

namespace {

// Oracle: minimise the exact point-to-segment distance along the first segment.
double oracle(const Segment& a, const Segment& b) {
  auto f = [&](double s) { return point_segment_distance(a.p0 + s * (a.p1 - a.p0), b); };
  double lo = 0, hi = 1;
  for (int i = 0; i < 200; ++i) {
    const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (f(m1) < f(m2)) hi = m2;
    else lo = m1;
  }
  return std::min({f(lo), f(0), f(1), point_segment_distance(b.p0, a), point_segment_distance(b.p1, a)});
}

}  // namespace

TEST_CASE("segments: parallel, collinear and zero-length", "[geometry][segment]") {
  SECTION("parallel with overlap: the offset, at an interior pair") {
    const auto r = closest_points({{0, 0, 0}, {10, 0, 0}}, {{4, 3, 0}, {20, 3, 0}});
    CHECK(r.distance == Approx(3).epsilon(1e-15));
    CHECK(r.interior);
    CHECK(r.point_a.x() > 4);
    CHECK(r.point_a.x() < 10);
  }
  SECTION("parallel without overlap: between the nearest ends") {
    const auto r = closest_points({{0, 0, 0}, {10, 0, 0}}, {{13, 4, 0}, {20, 4, 0}});
    CHECK(r.distance == Approx(5).epsilon(1e-15));
    CHECK_FALSE(r.interior);
  }
  SECTION("anti-parallel overlap") {
    const auto r = closest_points({{0, 0, 0}, {10, 0, 0}}, {{8, 0, 2}, {-5, 0, 2}});
    CHECK(r.distance == Approx(2).epsilon(1e-15));
    CHECK(r.interior);
  }
  SECTION("collinear: overlapping is 0, disjoint is the gap") {
    CHECK(closest_points({{0, 0, 0}, {10, 0, 0}}, {{5, 0, 0}, {15, 0, 0}}).distance == 0);
    CHECK(closest_points({{0, 0, 0}, {10, 0, 0}}, {{12.5, 0, 0}, {15, 0, 0}}).distance == Approx(2.5));
  }
  SECTION("zero-length segments are points") {
    CHECK(closest_points({{1, 1, 1}, {1, 1, 1}}, {{1, 1, 4}, {1, 1, 4}}).distance == Approx(3));
    CHECK(closest_points({{1, 2, 0}, {1, 2, 0}}, {{0, 0, 0}, {10, 0, 0}}).distance == Approx(2));
    CHECK(closest_points({{0, 0, 0}, {10, 0, 0}}, {{3, 0, 5}, {3, 0, 5}}).distance == Approx(5));
  }
  SECTION("crossing segments touch") {
    CHECK(closest_points({{-1, 0, 0}, {1, 0, 0}}, {{0, -1, 0}, {0, 1, 0}}).distance == 0);
  }
}

TEST_CASE("segments: near-parallel axes down to 1e-12 rad, offset by 1e6", "[geometry][segment][stiff]") {
  for (const double offset : {0.0, 1e6}) {
    for (const double eps : {1e-3, 1e-6, 1e-9, 1e-12}) {
      // The common perpendicular is the z axis through the midpoints: distance h exactly.
      const Vec3 o(offset, offset, offset);
      const double h = 0.75, L = 100;
      const Vec3 dir(std::cos(eps), std::sin(eps), 0);
      const Segment a{o + Vec3(-L / 2, 0, 0), o + Vec3(L / 2, 0, 0)};
      const Segment b{o + Vec3(0, 0, h) - dir * (L / 2), o + Vec3(0, 0, h) + dir * (L / 2)};
      const auto r = closest_points(a, b);
      INFO("eps " << eps << " offset " << offset);
      CHECK(std::abs(r.distance - h) <= 1e-9 * L);
      CHECK(std::abs(closest_points(b, a).distance - h) <= 1e-9 * L);
    }
  }
}

TEST_CASE("segments: random pairs agree with the golden-section oracle", "[geometry][segment]") {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-10, 10);
  auto v = [&] { return mtcs_test::draw_vec3(u, rng); };
  for (int i = 0; i < 2000; ++i) {
    Segment a{v(), v()}, b{v(), v()};
    if (i % 4 == 1) b.p1 = b.p0 + (a.p1 - a.p0) * 0.7;                      // parallel
    if (i % 4 == 2) b.p1 = b.p0 + (a.p1 - a.p0) * 0.7 + Vec3(1e-9, 0, 0);   // near-parallel
    if (i % 8 == 3) b.p1 = b.p0;                                              // a point
    const double d = closest_points(a, b).distance;
    const double ref = oracle(a, b);
    INFO("case " << i);
    REQUIRE(d <= ref + 1e-12);
    REQUIRE(d >= ref - 1e-9);
  }
}
