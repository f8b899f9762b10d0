// Solid cylinder vs triangle against closed forms and an independent reference: the distance
// from a triangle point to the solid cylinder is convex over the triangle (a distance to a
// convex set), so nested golden-section searches over the triangle's parameters find its minimum
// to rounding, with no knowledge of features.

#include <catch2/catch.hpp>
#include <cmath>
#include <random>

#include "mtcs/geometry/cylinder_triangle_distance.h"
#include "support/random_draws.h"

using namespace mtcs::geometry;

namespace {

double point_solid_distance(const Vec3& p, const Cylinder& c) {
  const Vec3 d = c.p1 - c.p0;
  const double len = d.norm();
  const Vec3 w = len > 0 ? Vec3(d / len) : Vec3::UnitZ();
  const double t = (p - c.p0).dot(w);
  const double rho = (p - c.p0 - t * w).norm();
  const double axial = std::max({0.0, -t, t - len}), radial = std::max(0.0, rho - c.radius);
  return std::hypot(axial, radial);
}

// Minimum of a convex f on [lo, hi] by golden-section search, to rounding.
template <class F>
double golden_min(F&& f, double lo, double hi) {
  const double g = (std::sqrt(5.0) - 1) / 2;
  double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo), f1 = f(x1), f2 = f(x2);
  for (int i = 0; i < 90 && hi - lo > 0; ++i) {
    if (f1 <= f2) hi = x2, x2 = x1, f2 = f1, x1 = hi - g * (hi - lo), f1 = f(x1);
    else lo = x1, x1 = x2, f1 = f2, x2 = lo + g * (hi - lo), f2 = f(x2);
  }
  return std::min({f1, f2, f(lo), f(hi)});
}

double reference(const Cylinder& c, const Triangle& t) {
  return golden_min([&](double s) {
    return golden_min([&](double u) {
      return point_solid_distance(t.a + s * (t.b - t.a) + u * (t.c - t.a), c);
    }, 0.0, 1.0 - s);
  }, 0.0, 1.0);
}

double scale(const Cylinder& c, const Triangle& t) {
  const Vec3 mid = (c.p0 + c.p1) / 2;
  return std::max({1.0, (c.p1 - c.p0).norm(), c.radius, (t.a - mid).norm(), (t.b - mid).norm(), (t.c - mid).norm()});
}

void check_exact(const Cylinder& c, const Triangle& t, double expected) {
  const auto r = distance(c, t);
  INFO("expected " << expected << " got " << r.distance);
  CHECK(!r.bounded);
  CHECK(std::abs(r.distance - expected) <= 1e-12 * scale(c, t));
  CHECK(r.intersecting() == (expected == 0));
  if (!r.bounded) {  // the witnesses are points of the two sets, as far apart as the distance
    CHECK(point_solid_distance(r.on_cylinder, c) <= 1e-12 * scale(c, t));
    CHECK(std::abs((r.on_cylinder - r.on_triangle).norm() - r.distance) <= 1e-12 * scale(c, t));
  }
}

}  // namespace

TEST_CASE("cylinder-triangle closed forms", "[geometry][cylinder_triangle]") {
  const Triangle floor{{-50, -50, 0}, {50, -50, 0}, {0, 80, 0}};
  SECTION("shell parallel to a face at a known gap") {
    for (const double g : {3.0, 1e-3, 1e-9})
      check_exact({{-10, 0, 2 + g}, {10, 0, 2 + g}, 2}, floor, g);
  }
  SECTION("end disk facing a triangle") {
    for (const double g : {3.0, 1e-6}) check_exact({{0, 0, g}, {0, 0, 20}, 5}, floor, g);
    // tilted by a small angle: the lowest rim point carries the distance
    const double a = 1e-4, g = 0.5, r = 5;
    check_exact({{0, 0, g + r * std::sin(a)}, {20 * std::sin(a), 0, g + r * std::sin(a) + 20 * std::cos(a)}, r}, floor, g);
  }
  SECTION("triangle edge below the rim, where the capsule is wrong") {
    // Cylinder along z from the origin, radius 2; the triangle lies in the plane x = 2 + g below
    // z = -1: the nearest pair is the rim point (2, 0, 0) and the edge point (2 + g, 0, -1).
    for (const double g : {0.5, 1e-8}) {
      const Triangle wall{{2 + g, -5, -1}, {2 + g, 5, -1}, {2 + g, 0, -9}};
      check_exact({{0, 0, 0}, {0, 0, 10}, 2}, wall, std::hypot(g, 1.0));
    }
    // The edge touches the rim: contact.
    check_exact({{0, 0, 0}, {0, 0, 10}, 2}, {{2, -5, 0}, {2, 5, 0}, {2, 0, -9}}, 0);
  }
  SECTION("intersections") {
    check_exact({{0, 0, -5}, {0, 0, 5}, 1}, floor, 0);                                 // axis crosses
    check_exact({{0, 0, 0}, {0, 0, 10}, 3}, {{0.1, 0, 5}, {0, 0.1, 5}, {0, 0, 5.1}}, 0);  // triangle inside
    // only a rim crosses the plane (the axis stays above it), inside the triangle
    check_exact({{0, 0, 0.5}, {30, 0, 10.5}, 3}, floor, 0);
    // the disk lies in the plane of a large triangle
    check_exact({{0, 0, 0}, {0, 0, 5}, 1}, floor, 0);
  }
}

TEST_CASE("cylinder-triangle upper bound", "[geometry][cylinder_triangle]") {
  const Triangle floor{{-50, -50, 0}, {50, -50, 0}, {0, 80, 0}};
  const Cylinder c{{-10, 0, 7}, {10, 0, 7}, 2};  // distance 5
  auto r = distance(c, floor, {.upper_bound = 4});
  CHECK(r.bounded);
  CHECK(r.distance >= 4);
  r = distance(c, floor, {.upper_bound = 6});
  CHECK(!r.bounded);
  CHECK(r.distance == Approx(5).epsilon(1e-14));
}

TEST_CASE("cylinder-triangle random and stiff cases against the convex reference", "[geometry][cylinder_triangle]") {
  std::mt19937_64 rng(20261123);
  std::uniform_real_distribution<double> u(-1, 1);
  auto vec = [&] { return mtcs_test::draw_vec3(u, rng); };
  int checked = 0, touching = 0;
  for (int i = 0; i < 3000; ++i) {
    const double size = std::pow(10.0, 3 * u(rng));  // triangles from 1e-3 to 1e3
    Cylinder c{vec() * 3, vec() * 3, 0.2 + std::abs(u(rng))};
    const Vec3 center = vec() * 4;
    Triangle t{center + vec() * size, center + vec() * size, center + vec() * size};
    switch (i % 4) {
      case 1: {  // plane nearly parallel to the axis
        const Vec3 w = (c.p1 - c.p0).normalized();
        const Vec3 side = w.unitOrthogonal();
        const double tilt = std::pow(10.0, -1 - 8 * std::abs(u(rng)));
        const Vec3 dir = (w + tilt * w.cross(side)).normalized();
        t = {center, center + size * dir, center + size * side};
        break;
      }
      case 2: {  // plane nearly parallel to the end disks
        const Vec3 w = (c.p1 - c.p0).normalized();
        const Vec3 e1 = w.unitOrthogonal(), e2 = w.cross(e1);
        const double tilt = std::pow(10.0, -1 - 8 * std::abs(u(rng)));
        t = {center, center + size * (e1 + tilt * w), center + size * e2};
        break;
      }
      default: break;
    }
    const double expected = reference(c, t);
    const double s = scale(c, t);
    const auto r = distance(c, t);
    INFO("case " << i << " expected " << expected << " got " << r.distance);
    REQUIRE(!r.bounded);
    // The reference is an attained value (an upper bound) converged to about 1e-13 S.
    CHECK(r.distance <= expected + 1e-12 * s);
    CHECK(r.distance >= expected - 1e-9 * s);
    if (expected > 1e-9 * s) CHECK(!r.intersecting());
    touching += r.intersecting();
    ++checked;
    // Skipping edges (a mesh query examines each shared edge once): two complementary halves
    // give the whole triangle, and each reports what it examined.
    const auto first = distance(c, t, {}, 0b110), rest = distance(c, t, {}, 0b001);
    CHECK(std::abs(std::min(first.distance, rest.distance) - r.distance) <= 1e-12 * s);
    CHECK((std::min(first.distance, rest.distance) == 0) == r.intersecting());
    CHECK((first.edges_examined & 0b110) == 0);
    CHECK((rest.edges_examined & 0b001) == 0);
  }
  CHECK(checked == 3000);
  CHECK(touching > 100);  // the set exercises both verdicts
}

TEST_CASE("cylinder-triangle inside certified bounds from a dense grid", "[geometry][cylinder_triangle]") {
  // The distance from a triangle point to the solid cylinder is 1-Lipschitz: over a barycentric
  // grid of step 1/N every triangle point is within (longest edge) / N of a grid point, so
  // [min over the grid - that radius, min over the grid] holds the true distance.
  std::mt19937_64 rng(61);
  std::uniform_real_distribution<double> u(-1, 1);
  auto vec = [&] { return mtcs_test::draw_vec3(u, rng); };
  constexpr int N = 400;
  int separated = 0;
  for (int i = 0; i < 150; ++i) {
    const Cylinder c{vec() * 2, vec() * 2, 0.1 + 0.5 * std::abs(u(rng))};
    const Vec3 center = vec() * 2.5;
    const Triangle t{center + vec(), center + vec(), center + vec()};
    double grid = std::numeric_limits<double>::infinity();
    for (int a = 0; a <= N; ++a)
      for (int b = 0; a + b <= N; ++b)
        grid = std::min(grid, point_solid_distance(t.a + (double(a) / N) * (t.b - t.a) + (double(b) / N) * (t.c - t.a), c));
    const double radius = std::max({(t.b - t.a).norm(), (t.c - t.b).norm(), (t.a - t.c).norm()}) / N;
    const auto r = distance(c, t);
    INFO("case " << i << " grid [" << grid - radius << ", " << grid << "] got " << r.distance);
    CHECK(r.distance <= grid + 1e-12);
    CHECK(r.distance >= grid - radius - 1e-12);
    if (grid - radius > 0) {
      CHECK(!r.intersecting());
      ++separated;
    }
    if (grid == 0) CHECK(r.intersecting());
  }
  CHECK(separated > 50);
}

TEST_CASE("cylinder-triangle verdicts within rounding of touching", "[geometry][cylinder_triangle]") {
  // A tilted end disk (axis along (3, 0, 4): the rim dips r 3/5 = 3 below its centre) whose
  // lowest rim point is j ulps of 3 above or below the plane z = 0. Every input is an exact
  // double, so the true distance is exactly max(0, h0 - 3); in double the rim's reach carries
  // rounding of that size, which used to flip the verdict.
  const Triangle t{{-100, -100, 0}, {100, -100, 0}, {0, 100, 0}};
  for (int j = -3; j <= 3; ++j) {
    for (const double x : {1.0, -7.0, 30.5}) {
      const double h0 = 3 + j * std::ldexp(1.0, -50);
      const Cylinder c{{x, 2, h0}, {x + 0.75, 2, h0 + 1}, 5};
      INFO("j = " << j << ", x = " << x);
      CHECK(distance(c, t).distance == (j > 0 ? h0 - 3 : 0.0));
    }
  }
  // An end disk parallel to the plane, 2^-60 above or below it (on it: touching).
  for (const int j : {-1, 0, 1}) {
    const double h0 = j * std::ldexp(1.0, -60);
    CHECK(distance(Cylinder{{1, 2, h0}, {1, 2, 10}, 1}, t).distance == (j > 0 ? h0 : 0.0));
  }
}
