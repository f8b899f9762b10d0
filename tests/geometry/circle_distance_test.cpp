// Circle-line, circle-circle and circle-disk distances: closed forms, radius < 1 (where the
// source paper found Vranek's code failing), and random cases against a dense-sampling oracle
// that uses only closed-form point distances.

#include <catch2/catch.hpp>
#include <Eigen/Geometry>
#include <cmath>
#include <random>

#include "geometry/circle_distance.h"

using namespace mtcs::geometry;

namespace {

Vec3 circle_point(const Circle& c, double theta) {
  Vec3 u = c.normal.unitOrthogonal(), v = c.normal.normalized().cross(u);
  return c.center + c.radius * (std::cos(theta) * u + std::sin(theta) * v);
}

// The kernels stop within tolerance * max(1, S) = 1e-12 * S of the minimum; S < 10 here.
// Dense sampling of the circle, then golden-section refinement around the best sample.
template <class F>
double oracle(const Circle& c, F&& dist) {
  const int n = 20000;
  int best = 0;
  double bestv = dist(circle_point(c, 0));
  for (int k = 1; k < n; ++k) {
    const double v = dist(circle_point(c, 2 * M_PI * k / n));
    if (v < bestv) bestv = v, best = k;
  }
  double lo = 2 * M_PI * (best - 1) / n, hi = 2 * M_PI * (best + 1) / n;
  for (int i = 0; i < 100; ++i) {
    const double m1 = lo + (hi - lo) / 3, m2 = hi - (hi - lo) / 3;
    if (dist(circle_point(c, m1)) < dist(circle_point(c, m2))) hi = m2;
    else lo = m1;
  }
  return std::min(bestv, dist(circle_point(c, (lo + hi) / 2)));
}

double point_line(const Vec3& p, const Vec3& o, const Vec3& d) {
  const Vec3 w = d.normalized();
  return ((p - o) - (p - o).dot(w) * w).norm();
}
double point_circle(const Vec3& p, const Circle& c, bool filled) {
  const Vec3 n = c.normal.normalized();
  const double h = (p - c.center).dot(n);
  const double rho = ((p - c.center) - h * n).norm();
  const double dr = filled ? std::max(0.0, rho - c.radius) : rho - c.radius;
  return std::hypot(h, dr);
}

}  // namespace

TEST_CASE("circle-line: closed forms", "[geometry][circle]") {
  const Circle c{{1, 2, 3}, {0, 0, 1}, 2};
  SECTION("the axis is at distance r") {
    CHECK(circle_line_distance(c, {1, 2, 0}, {0, 0, 1}).distance == Approx(2).epsilon(1e-14));
  }
  SECTION("a line in the plane through the centre touches") {
    CHECK(circle_line_distance(c, {1, 2, 3}, {1, 1, 0}).distance == Approx(0).margin(1e-12));
  }
  SECTION("a line above the plane, outside the circle's shadow") {
    const double h = 0.5, q = 3;  // height above the plane, distance from the axis
    const auto r = circle_line_distance(c, {1 + q, 2, 3 + h}, {0, 1, 0});
    CHECK(r.distance == Approx(std::hypot(h, q - 2)).epsilon(1e-13));
  }
  SECTION("a line above the plane crossing the circle's shadow is at the height") {
    const auto r = circle_line_distance(c, {1 + 1.2, 2, 3 + 0.25}, {0, 1, 0});
    CHECK(r.distance == Approx(0.25).epsilon(1e-12));
  }
  SECTION("radius < 1") {
    const Circle small{{0, 0, 0}, {0, 1, 0}, 1e-3};
    CHECK(circle_line_distance(small, {0, 0, 0}, {0, 1, 0}).distance == Approx(1e-3).epsilon(1e-12));
    CHECK(circle_line_distance(small, {0.5, 0, 0}, {0, 0, 1}).distance == Approx(0.5 - 1e-3).epsilon(1e-12));
  }
}

TEST_CASE("circle-circle and circle-disk: closed forms", "[geometry][circle]") {
  const Circle a{{0, 0, 0}, {0, 0, 1}, 3};
  CHECK(circle_circle_distance(a, {{0, 0, 0}, {0, 0, 1}, 1}).distance == Approx(2).epsilon(1e-14));
  CHECK(circle_circle_distance(a, {{0, 0, 4}, {0, 0, 1}, 1}).distance == Approx(std::hypot(4, 2)).epsilon(1e-14));
  // Linked like a chain, the second centred on the first: every point at its radius.
  CHECK(circle_circle_distance(a, {{3, 0, 0}, {0, 1, 0}, 1}).distance == Approx(1).epsilon(1e-12));
  // Two circles through a common point.
  CHECK(circle_circle_distance(a, {{3, 0, 1}, {0, 1, 0}, 1}).distance == Approx(0).margin(1e-12));
  // A disk under the circle: the height; a circle piercing the disk: 0.
  CHECK(circle_disk_distance({{0, 0, 2}, {0, 0, 1}, 1}, {{0, 0, 0}, {0, 0, 1}, 5}).distance == Approx(2));
  CHECK(circle_disk_distance({{0, 0, 0}, {1, 0, 0}, 1}, {{0, 0, 0}, {0, 0, 1}, 5}).distance == Approx(0).margin(1e-12));
  // Beside the disk: rim to rim.
  CHECK(circle_disk_distance({{10, 0, 0}, {0, 0, 1}, 1}, {{0, 0, 0}, {0, 0, 1}, 5}).distance == Approx(4));
}

TEST_CASE("circle distances: random cases against the sampling oracle", "[geometry][circle]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-3, 3), r(0.05, 3);
  // Drawn in sequence (a constructor's arguments are evaluated in an unspecified order): the
  // same cases for every compiler. Case 68 holds two basins 0.4 rad apart, the deeper one between
  // two samples (experiments/ci/README.md).
  auto v = [&] {
    const double x = u(rng), y = u(rng), z = u(rng);
    return Vec3(x, y, z);
  };
  for (int i = 0; i < 150; ++i) {
    const Circle c{v(), v().normalized(), r(rng)};
    const Circle o{v(), v().normalized(), r(rng)};
    const Vec3 lo = v(), ld = v();
    INFO("case " << i);
    const double dl = circle_line_distance(c, lo, ld).distance;
    const double rl = oracle(c, [&](const Vec3& p) { return point_line(p, lo, ld); });
    CHECK(dl <= rl + 1e-10);
    CHECK(dl >= rl - 1e-9);
    const double dc = circle_circle_distance(c, o).distance;
    const double rc = oracle(c, [&](const Vec3& p) { return point_circle(p, o, false); });
    CHECK(dc <= rc + 1e-10);
    CHECK(dc >= rc - 1e-9);
    const double dd = circle_disk_distance(c, o).distance;
    const double rd = oracle(c, [&](const Vec3& p) { return point_circle(p, o, true); });
    CHECK(dd <= rd + 1e-10);
    CHECK(dd >= rd - 1e-9);
  }
}
