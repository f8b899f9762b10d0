// The heat input's tree against the direct sum of the triangles' closed forms.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "support/random_draws.h"
#include "thermal/kernels/heat_source_tree.h"

using namespace mtcs::thermal;
using mtcs_test::draw_vec3;

namespace {

double direct(const std::vector<HeatedTriangle>& ts, const Vec3& p) {
  double sum = 0;
  for (const HeatedTriangle& t : ts) sum += t.flux * triangle_potential(t.a, t.b, t.c, p);
  return sum;
}

// A wavy sheet of n x n cells, two triangles each, over [0, 100]^2 at z ~ 50: a cavity wall's
// heat input, fluxes 0.5-1.5 (plus a few zero ones, which the tree leaves out).
std::vector<HeatedTriangle> sheet(int n, std::mt19937& rng) {
  std::uniform_real_distribution<double> f(0.5, 1.5);
  auto at = [&](int i, int j) {
    const double x = 100.0 * i / n, y = 100.0 * j / n;
    return Vec3(x, y, 50 + 5 * std::sin(x / 13) * std::cos(y / 17));
  };
  std::vector<HeatedTriangle> ts;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double q1 = (i + j) % 29 == 0 ? 0.0 : f(rng), q2 = f(rng);
      ts.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1), q1});
      ts.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1), q2});
    }
  return ts;
}

}  // namespace

TEST_CASE("heat source tree: theta 0 is the direct sum", "[thermal][heat_tree]") {
  std::mt19937 rng(7);
  const auto ts = sheet(12, rng);
  const HeatSourceTree tree(ts, 0.0);
  std::uniform_real_distribution<double> u(-20, 120);
  for (int k = 0; k < 50; ++k) {
    const Vec3 p = draw_vec3(u, rng);
    const double want = direct(ts, p);
    CHECK(std::abs(tree.potential(p) - want) <= 1e-12 * std::abs(want));
  }
}

TEST_CASE("heat source tree: one far triangle, error of the octupole order", "[thermal][heat_tree]") {
  // The expansion to the quadrupole leaves O((s/d)^3) of the potential: 10x farther, 1000x
  // smaller. A missing or wrong quadrupole would leave O((s/d)^2).
  const std::vector<HeatedTriangle> ts{{Vec3(0, 0, 0), Vec3(3, 0.5, 0.2), Vec3(0.7, 2, -0.4), 1.3}};
  const HeatSourceTree tree(ts, 0.5);
  const Vec3 dir = Vec3(0.6, -0.3, 0.74).normalized();
  double previous = 0;
  for (const double d : {10.0, 100.0, 1000.0}) {
    const Vec3 p = d * dir;
    const double want = direct(ts, p);
    const double rel = std::abs(tree.potential(p) - want) / want;
    CHECK(rel < 5e-3 * std::pow(10.0 / d, 3));
    if (previous > 0) CHECK(rel < previous / 300);
    previous = rel;
  }
}

TEST_CASE("heat source tree: a sheet of 12 800 triangles at points near and far", "[thermal][heat_tree]") {
  std::mt19937 rng(11);
  const auto ts = sheet(80, rng);
  std::uniform_real_distribution<double> u(-50, 150), on(0, 100);
  for (const double theta : {0.1, 0.2, 0.3}) {
    const HeatSourceTree tree(ts, theta);
    CHECK(tree.size() < ts.size());  // the zero-flux triangles left out
    double worst = 0;
    for (int k = 0; k < 200; ++k) {
      // Half of the points on or just off the sheet (where the near triangles dominate).
      Vec3 p = draw_vec3(u, rng);
      if (k % 2) p = Vec3(on(rng), on(rng), 50 + (k % 4 == 1 ? 0.0 : 2.0));
      const double want = direct(ts, p);
      worst = std::max(worst, std::abs(tree.potential(p) - want) / std::abs(want));
    }
    INFO("theta " << theta << ": worst relative error " << worst);
    CHECK(worst < 0.02 * std::pow(theta, 3));  // measured: 2.9e-6, 3.3e-5, 2.0e-4
  }
}
