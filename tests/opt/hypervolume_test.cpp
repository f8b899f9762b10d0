// Hypervolume against the exact values of shared/cases/hv_fronts (42 fronts, d = 2..5), and
// contributions against an independent exact oracle: HV(S) - HV(S \ {p}) over the grid of all
// coordinates, summed in CGAL's exact rationals (Gmpq).

#include <CGAL/Gmpq.h>

#include <catch2/catch.hpp>
#include <fstream>
#include <map>
#include <random>
#include <sstream>

#include "mtcs/io/front_file.h"
#include "mtcs/opt/hypervolume.h"
#include "support/paths.h"

using namespace mtcs::opt;

namespace {

using Front = mtcs::io::FrontFile;
Front read(const std::string& path) { return mtcs::io::read_front(path); }

// Exact hypervolume: every cell of the grid spanned by the coordinates, counted once if some
// point dominates it, volumes summed as exact rationals. Small sets only.
CGAL::Gmpq exact_hv(const std::vector<Point>& pts, const Point& ref) {
  const std::size_t d = ref.size();
  std::vector<std::vector<double>> axes(d);
  for (std::size_t k = 0; k < d; ++k) {
    axes[k].push_back(ref[k]);
    for (const Point& p : pts)
      if (p[k] < ref[k]) axes[k].push_back(p[k]);
    std::sort(axes[k].begin(), axes[k].end());
    axes[k].erase(std::unique(axes[k].begin(), axes[k].end()), axes[k].end());
  }
  CGAL::Gmpq total = 0;
  std::vector<std::size_t> cell(d, 0);
  for (;;) {
    bool valid = true;
    for (std::size_t k = 0; k < d; ++k) valid = valid && cell[k] + 1 < axes[k].size();
    if (valid) {
      bool covered = false;
      for (const Point& p : pts) {
        bool dom = true;
        for (std::size_t k = 0; k < d && dom; ++k) dom = p[k] <= axes[k][cell[k]] && p[k] < ref[k];
        covered = covered || dom;
      }
      if (covered) {
        CGAL::Gmpq v = 1;
        for (std::size_t k = 0; k < d; ++k) v *= CGAL::Gmpq(axes[k][cell[k] + 1]) - CGAL::Gmpq(axes[k][cell[k]]);
        total += v;
      }
    }
    std::size_t k = 0;
    while (k < d && ++cell[k] >= axes[k].size()) cell[k++] = 0;
    if (k == d) break;
  }
  return total;
}

}  // namespace

TEST_CASE("hypervolume: the 42 certified fronts to 1e-12 relative", "[opt][hypervolume]") {
  std::ifstream expected(MTCS_TEST_DATA + "/hv_fronts/expected.csv");
  std::string line;
  std::getline(expected, line);
  int fronts = 0;
  while (std::getline(expected, line)) {
    std::istringstream ss(line);
    std::string name, d, n, hv;
    std::getline(ss, name, ','), std::getline(ss, d, ','), std::getline(ss, n, ','), std::getline(ss, hv, ',');
    const Front f = read(MTCS_TEST_DATA + "/hv_fronts/" + name + ".txt");
    const double want = std::stod(hv);
    INFO(name);
    CHECK(std::abs(hypervolume(f.points, f.ref) - want) <= 1e-12 * want);
    ++fronts;
  }
  CHECK(fronts == 42);
}

TEST_CASE("hypervolume: contributions equal the exact leave-one-out differences", "[opt][hypervolume]") {
  std::mt19937_64 rng(12);
  std::uniform_int_distribution<int> coord(0, 20);
  for (std::size_t d = 2; d <= 5; ++d) {
    for (int trial = 0; trial < (d <= 3 ? 12 : 30); ++trial) {
      // Coarse coordinates make ties, duplicates and points on the reference boundary common.
      const int n = d <= 3 ? 9 : 7;
      std::vector<Point> pts(static_cast<std::size_t>(n), Point(d));
      for (auto& p : pts)
        for (double& v : p) v = coord(rng) / 20.0;
      if (trial % 3 == 0) pts[1] = pts[0];  // a duplicate
      const Point ref(d, 1.0);
      const CGAL::Gmpq all = exact_hv(pts, ref);
      CHECK(std::abs(hypervolume(pts, ref) - CGAL::to_double(all)) <= 1e-14);
      const auto c = contributions(pts, ref);
      for (std::size_t i = 0; i < pts.size(); ++i) {
        std::vector<Point> rest = pts;
        rest.erase(rest.begin() + long(i));
        const double exact = CGAL::to_double(all - exact_hv(rest, ref));
        INFO("d " << d << " trial " << trial << " point " << i);
        CHECK(std::abs(c[i] - exact) <= 1e-14);
        if (exact == 0) CHECK(c[i] == 0);
      }
      if (trial % 3 == 0) CHECK((c[0] == 0 && c[1] == 0));
    }
  }
}

TEST_CASE("hypervolume: reference boundary, dominated points, a tiny contribution", "[opt][hypervolume]") {
  const Point ref{1, 1};
  // On the boundary: no volume, no contribution, no effect on the others.
  CHECK(hypervolume({{0.5, 1.0}}, ref) == 0);
  CHECK(contributions({{0.5, 1.0}, {0.5, 0.5}}, ref) == std::vector<double>{0, 0.25});
  // Dominated: nothing.
  CHECK(contributions({{0.2, 0.2}, {0.4, 0.4}}, ref)[1] == 0);
  // A contribution of 1e-12 next to ones of about 0.1 is resolved.
  const double e = 1e-6;
  const auto c = contributions({{0.2, 0.6}, {0.6 - e, 0.6 - e}, {0.6, 0.2}}, ref);
  CHECK(c[1] == Approx(e * e).epsilon(1e-3));
}

TEST_CASE("hypervolume: tiny contributions in 3 to 5 objectives match their closed form", "[opt][hypervolume]") {
  // Corners p_k (0.2 in objective k, 0.6 elsewhere) and q = (0.6 - e, ...): q alone covers the
  // points of its box with at least two objectives below 0.6, sum over m >= 2 of
  // C(d, m) e^m 0.4^(d - m): about 1e-12 of q's box, the case where box-minus-the-rest cancels.
  for (std::size_t d = 3; d <= 5; ++d) {
    const double e = 1e-6;
    std::vector<Point> pts;
    for (std::size_t k = 0; k < d; ++k) {
      Point p(d, 0.6);
      p[k] = 0.2;
      pts.push_back(p);
    }
    pts.push_back(Point(d, 0.6 - e));
    long double expected = 0, binomial = 1;
    for (std::size_t m = 1; m <= d; ++m) {
      binomial = binomial * static_cast<long double>(d - m + 1) / static_cast<long double>(m);
      if (m >= 2) expected += binomial * std::pow(static_cast<long double>(e), int(m)) * std::pow(0.4L, int(d - m));
    }
    const auto c = contributions(pts, Point(d, 1.0));
    INFO("d = " << d);
    CHECK(std::abs(c.back() - double(expected)) <= 1e-9 * double(expected));
  }
}

TEST_CASE("hypervolume: 3-D contributions on a large front full of ties equal leave-one-out differences", "[opt][hypervolume]") {
  std::mt19937_64 rng(7);
  std::uniform_int_distribution<int> coord(0, 12);
  std::vector<Point> pts;
  while (pts.size() < 300) {
    // Near the plane x + y + z = 1.5 on a coarse grid: many mutually non-dominated points, ties.
    const double x = coord(rng) / 12.0, y = coord(rng) / 12.0;
    const double z = std::clamp(std::round((1.5 - x - y) * 12.0 + coord(rng) % 3 - 1) / 12.0, 0.0, 1.0);
    pts.push_back({x, y, z});
  }
  const Point ref{1.05, 1.05, 1.05};
  const double all = hypervolume(pts, ref);
  const auto c = contributions(pts, ref);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    std::vector<Point> rest = pts;
    rest.erase(rest.begin() + long(i));
    INFO("point " << i);
    CHECK(std::abs(c[i] - (all - hypervolume(rest, ref))) <= 1e-14);
  }
}

#include "bench/pagmo_peer.h"

TEST_CASE("hypervolume: pagmo agrees on every certified front, 2-D contributions identical", "[opt][hypervolume]") {
  for (const char* name : {"linear_d2_n1000", "random_d3_n1000", "sphere_d4_n100", "random_d5_n100", "sphere_d2_n100"}) {
    const Front f = read(std::string(MTCS_TEST_DATA + "/hv_fronts/") + name + ".txt");
    const double ours = hypervolume(f.points, f.ref), theirs = mtcs::bench::pagmo_hypervolume(f.points, f.ref);
    INFO(name);
    CHECK(std::abs(ours - theirs) <= 1e-12 * ours);
    if (f.ref.size() == 2) CHECK(contributions(f.points, f.ref) == mtcs::bench::pagmo_contributions(f.points, f.ref));
  }
}
