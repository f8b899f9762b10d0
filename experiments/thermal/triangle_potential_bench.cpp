// The triangle potential three ways on 200 000 random triangle/point pairs (model_build.md,
// 2026-11-29): the per-edge atan form before (copied here: the library no longer has it), the
// library's one atan2 with one log per edge (triangle_potential, the triangle's geometry taken
// per call), and the same with the geometry kept (TriangleSource); accuracy of the second
// against the first. Built with the thermal library's flags (src/thermal/CMakeLists.txt), from the
// checkout after scripts/build.sh:
//   g++ -O3 -fno-math-errno -fno-trapping-math -std=c++20 -Isrc -Iinclude -I/usr/include/eigen3 \
//     experiments/thermal/triangle_potential_bench.cpp build/src/thermal/libmtcs_thermal.a -o tpb && ./tpb
#include <Eigen/Dense>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include "thermal/segment_potential.h"

using mtcs::thermal::Vec3;
namespace old_ {
double edge_log(double l_minus, double l_plus, double R_minus, double R_plus, double R0) {
  if (l_minus >= 0) return std::log((R_plus + l_plus) / (R_minus + l_minus));
  if (l_plus <= 0) return std::log((R_minus - l_minus) / (R_plus - l_plus));
  return std::asinh(l_plus / R0) - std::asinh(l_minus / R0);
}
double triangle_potential(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& s) {
  const Vec3 normal_area = (b - a).cross(c - a);
  const double twice_area = normal_area.norm();
  if (twice_area == 0) return 0;
  const Vec3 n = normal_area / twice_area;
  const double d = (s - a).dot(n);
  const double ad = std::abs(d);
  const Vec3 p = s - d * n;
  const Vec3 corners[3] = {a, b, c};
  double sum_log = 0, sum_angle = 0;
  for (int i = 0; i < 3; ++i) {
    const Vec3& p0 = corners[i];
    const Vec3& p1 = corners[(i + 1) % 3];
    const Vec3 edge = p1 - p0;
    const double edge_length = edge.norm();
    if (edge_length == 0) continue;
    const Vec3 t = edge / edge_length;
    const Vec3 m = t.cross(n);
    const double P0 = (p0 - p).dot(m);
    const double l_minus = (p0 - p).dot(t);
    const double l_plus = (p1 - p).dot(t);
    const double R0sq = P0 * P0 + d * d;
    const double R_minus = (s - p0).norm();
    const double R_plus = (s - p1).norm();
    if (R0sq <= 1e-24 * edge_length * edge_length) continue;
    const double R0 = std::sqrt(R0sq);
    if (P0 != 0) sum_log += P0 * edge_log(l_minus, l_plus, R_minus, R_plus, R0);
    if (ad != 0 && P0 != 0) {
      sum_angle += std::atan(P0 * l_plus / (R0sq + ad * R_plus)) -
                   std::atan(P0 * l_minus / (R0sq + ad * R_minus));
    }
  }
  return sum_log - ad * sum_angle;
}
}
int main() {
  std::mt19937_64 g(1);
  std::uniform_real_distribution<double> u(-1, 1);
  double worst = 0; int wi=-1;
  std::vector<std::array<Vec3,4>> cases;
  for (int k = 0; k < 200000; ++k) {
    Vec3 a(u(g), u(g), 0), b(u(g), u(g), 0), c(u(g), u(g), 0);
    double sc = std::pow(10.0, 3 * u(g));
    Vec3 s(u(g), u(g), u(g));
    int mode = k % 5;
    if (mode == 1) s.z() = 1e-9 * u(g);
    if (mode == 2) s = a + (b - a) * (0.5 + u(g)) + Vec3(0, 0, 1e-6 * u(g));
    if (mode == 3) s *= 100;
    if (mode == 4) { Vec3 off(1e4, -3e3, 50); a += off; b += off; c += off; s += off; }
    a *= sc; b *= sc; c *= sc; s *= sc;
    cases.push_back({a, b, c, s});
    double o = old_::triangle_potential(a, b, c, s), n = mtcs::thermal::triangle_potential(a, b, c, s);
    double scale = std::abs(o) + 1e-300;
    double e = std::abs(o - n) / scale;
    if (!(e <= worst)) { worst = e; wi = k; }
  }
  printf("worst rel diff %g at %d (mode %d)\n", worst, wi, wi % 5);
  auto time = [&](auto f) {
    auto t0 = std::chrono::steady_clock::now(); double acc = 0;
    for (int rep = 0; rep < 5; ++rep) for (auto& k : cases) acc += f(k[0], k[1], k[2], k[3]);
    return std::make_pair(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / (5 * cases.size()) * 1e9, acc);
  };
  auto [to, ao] = time(old_::triangle_potential);
  auto [tn, an] = time(mtcs::thermal::triangle_potential);
  auto [to2, ao2] = time(old_::triangle_potential);
  auto [tn2, an2] = time(mtcs::thermal::triangle_potential);
  printf("old %.1f ns new %.1f ns | old %.1f new %.1f\n", to, tn, to2, tn2);
  std::vector<mtcs::thermal::TriangleSource> tris;
  for (auto& k : cases) tris.emplace_back(k[0], k[1], k[2]);
  auto t0 = std::chrono::steady_clock::now(); double acc = 0;
  for (int rep = 0; rep < 5; ++rep) for (size_t i = 0; i < cases.size(); ++i) acc += tris[i].potential(cases[i][3]);
  printf("pre %.1f ns (%g vs %g)\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / (5 * cases.size()) * 1e9, acc, an);
}
