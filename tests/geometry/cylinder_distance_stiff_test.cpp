// Our own stiff cases, each with a closed form: near-parallel axes down to 1e-12 rad, radius
// 1e-4, length/radius 1e5, coordinates offset by 1e6, tangent contact, radius < 1. Then random
// pairs against two independent methods: the naive all-sub-distances baseline and FCL's GJK.

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "bench/fcl_peer.h"
#include "mtcs/geometry/cylinder_distance.h"
#include "support/random_draws.h"

using namespace mtcs::geometry;

namespace {

Cylinder shifted(const Cylinder& c, const Vec3& o) { return {c.p0 + o, c.p1 + o, c.radius}; }

void check_distance(const Cylinder& a, const Cylinder& b, double expected, Feature feature) {
  const double tol = 1e-9 * std::max(1.0, pair_scale(a, b));
  for (const bool swap : {false, true}) {
    const auto r = swap ? distance(b, a) : distance(a, b);
    CHECK(std::abs(r.distance - expected) <= tol);
    CHECK(r.feature == feature);
    CHECK(r.intersecting() == (expected == 0));
  }
}

}  // namespace

TEST_CASE("stiff: near-parallel axes down to 1e-12 rad", "[geometry][cylinder][stiff]") {
  for (const double offset : {0.0, 1e6}) {
    for (const double eps : {1e-3, 1e-6, 1e-9, 1e-12}) {
      // The common perpendicular is the z axis through both midpoints: distance h - ra - rb.
      const Vec3 o(offset, -offset, offset);
      const double L = 200, h = 3, ra = 1, rb = 0.5;
      const Vec3 dir(std::cos(eps), std::sin(eps), 0);
      const Cylinder a{o + Vec3(-L / 2, 0, 0), o + Vec3(L / 2, 0, 0), ra};
      const Cylinder b{o + Vec3(0, 0, h) - dir * (L / 2), o + Vec3(0, 0, h) + dir * (L / 2), rb};
      INFO("eps " << eps << " offset " << offset);
      check_distance(a, b, h - ra - rb, Feature::ShellShell);
    }
  }
}

TEST_CASE("stiff: tiny radius, long thin bores, offsets", "[geometry][cylinder][stiff]") {
  SECTION("radius 1e-4, crossing at a gap") {
    const Cylinder a{{-1, 0, 0}, {1, 0, 0}, 1e-4}, b{{0, -1, 2.5e-4}, {0, 1, 2.5e-4}, 1e-4};
    check_distance(a, b, 0.5e-4, Feature::ShellShell);
  }
  SECTION("length/radius 1e5, parallel") {
    const Cylinder a{{0, 0, 0}, {1e5, 0, 0}, 1}, b{{5e4, 3, 0}, {1.5e5, 3, 0}, 1};
    check_distance(a, b, 1, Feature::ShellShell);
  }
  SECTION("length/radius 1e5, end to end with a rim-rim gap") {
    const Cylinder a{{0, 0, 0}, {1e5, 0, 0}, 1}, b{{1e5 + 1, 5, 0}, {2e5, 5, 0}, 1};
    check_distance(a, b, std::hypot(1.0, 3.0), Feature::RimRim);
  }
  SECTION("coordinates offset by 1e6: rim to shell") {
    const Vec3 o(1e6, 1e6, -1e6);
    // b's bottom rim faces a's shell: a along x (r 2), b along z from 5 (r 1): gap 3.
    check_distance(shifted({{-10, 0, 0}, {10, 0, 0}, 2}, o), shifted({{1, 0, 5}, {1, 0, 15}, 1}, o), 3,
                   Feature::ShellRim);
  }
  SECTION("radius < 1: rims facing across a gap") {
    const Cylinder a{{0, 0, 0}, {0, 0, 1}, 0.3}, b{{5, 0, 2}, {5, 0, 3}, 0.2};
    check_distance(a, b, std::hypot(5 - 0.5, 1.0), Feature::RimRim);
  }
  SECTION("coaxial disks: disk-disk") {
    const Cylinder a{{0, 0, 0}, {0, 0, 1}, 0.75}, b{{0, 0, 1.5}, {0, 0, 4}, 0.25};
    check_distance(a, b, 0.5, Feature::DiskDisk);
  }
}

TEST_CASE("stiff: tangent contact is intersecting, a 1e-12 gap is not", "[geometry][cylinder][stiff]") {
  const double gap = std::ldexp(1.0, -40);  // ~9.1e-13, exact in binary
  SECTION("parallel shells") {
    check_distance({{0, 0, 0}, {10, 0, 0}, 1}, {{0, 3, 0}, {10, 3, 0}, 2}, 0, Feature::Intersecting);
    check_distance({{0, 0, 0}, {10, 0, 0}, 1}, {{0, 3 + gap, 0}, {10, 3 + gap, 0}, 2}, gap, Feature::ShellShell);
  }
  SECTION("crossed shells") {
    check_distance({{-5, 0, 0}, {5, 0, 0}, 1}, {{0, -5, 2}, {0, 5, 2}, 1}, 0, Feature::Intersecting);
    check_distance({{-5, 0, 0}, {5, 0, 0}, 1}, {{0, -5, 2 + gap}, {0, 5, 2 + gap}, 1}, gap, Feature::ShellShell);
  }
  SECTION("end disks face to face") {
    check_distance({{0, 0, 0}, {0, 0, 1}, 1}, {{0.5, 0, 1}, {0.5, 0, 3}, 1}, 0, Feature::Intersecting);
    check_distance({{0, 0, 0}, {0, 0, 1}, 1}, {{0.5, 0, 1 + gap}, {0.5, 0, 3}, 1}, gap, Feature::DiskDisk);
  }
  SECTION("a rim on a shell, offset by 1e6") {
    const Vec3 o(1e6, 1e6, 1e6);
    check_distance(shifted({{-10, 0, 0}, {10, 0, 0}, 2}, o), shifted({{0, 0, 2}, {0, 0, 12}, 1}, o), 0,
                   Feature::Intersecting);
    check_distance(shifted({{-10, 0, 0}, {10, 0, 0}, 2}, o),
                   shifted({{0, 0, 2 + std::ldexp(1.0, -30)}, {0, 0, 12}, 1}, o), std::ldexp(1.0, -30),
                   Feature::ShellRim);
  }
}

TEST_CASE("stiff: nested, crossing and junction pairs", "[geometry][cylinder][stiff]") {
  // A thin bore inside a fat one, touching nothing.
  check_distance({{0, 0, 0}, {0, 0, 10}, 3}, {{1, 0, 2}, {1, 0, 8}, 0.5}, 0, Feature::Intersecting);
  // A thin bore through the end disks of a short fat one, far from every rim and the axis.
  check_distance({{0, 0, 0}, {0, 0, 1}, 10}, {{5, 0, -50}, {5.1, 0, 50}, 0.1}, 0, Feature::Intersecting);
  // A T-junction: one bore ends inside another.
  check_distance({{-10, 0, 0}, {10, 0, 0}, 2}, {{0, 0, 1}, {0, 0, 20}, 1}, 0, Feature::Intersecting);
}

TEST_CASE("stiff: degenerate and extreme inputs stay finite", "[geometry][cylinder][stiff]") {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  std::uniform_int_distribution<int> expo(-12, 12);
  for (int i = 0; i < 20000; ++i) {
    auto v = [&] {
      const double x = u(rng), y = u(rng), z = u(rng), scale = std::ldexp(1.0, 3 * expo(rng));
      return Vec3(x * scale, y * scale, z * scale);
    };
    Cylinder a{v(), v(), std::abs(u(rng)) * std::ldexp(1.0, 2 * expo(rng))};
    Cylinder b{v(), v(), std::abs(u(rng)) * std::ldexp(1.0, 2 * expo(rng))};
    if (i % 5 == 0) a.p1 = a.p0;        // zero length
    if (i % 7 == 0) b.radius = 0;       // a segment
    if (i % 11 == 0) b.p1 = b.p0 + (a.p1 - a.p0) * 3;  // parallel
    const auto r = distance(a, b);
    INFO("case " << i);
    REQUIRE(std::isfinite(r.distance));
    REQUIRE(r.distance >= 0);
    REQUIRE(r.witness_a.allFinite());
  }
}

TEST_CASE("random pairs: agree with the naive baseline and with FCL", "[geometry][cylinder][oracle]") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-5, 5), r(0.05, 2);
  auto v = [&] { return mtcs_test::draw_vec3(u, rng); };
  int naive_bad = 0, fcl_bad = 0;
  for (int i = 0; i < 3000; ++i) {
    const Cylinder a{v(), v(), r(rng)}, b{v(), v(), r(rng)};
    const auto ours = distance(a, b);
    const double s = std::max(1.0, pair_scale(a, b));
    if (std::abs(distance_naive(a, b).distance - ours.distance) > 1e-9 * s) ++naive_bad;
    // GJK converges to ~1e-6 on these curved shapes: a coarse but independent check.
    const double fcl = mtcs::bench::FclPair(a, b).distance();
    if (std::abs(fcl - ours.distance) > 1e-3 * s) ++fcl_bad;
  }
  CHECK(naive_bad == 0);
  CHECK(fcl_bad == 0);
}
