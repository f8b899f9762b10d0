// The triangle potential three ways on 200 000 random triangle/point pairs (model_build.md,
// 2026-11-29): the per-edge atan form before, one atan2 with one log per edge, and the same
// with the geometry kept per triangle; accuracy of the second against the first.
// Build and run: g++ -O2 -march=x86-64 -I/usr/include/eigen3 triangle_potential_bench.cpp -o tpb && ./tpb
#include <Eigen/Dense>
#include <cmath>
#include <cstdio>
#include <random>
#include <chrono>
using Vec3 = Eigen::Vector3d;
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
namespace new_ {
double triangle_potential(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& s) {
  const Vec3 normal_area = (b - a).cross(c - a);
  const double twice_area = normal_area.norm();
  if (twice_area == 0) return 0;
  const Vec3 n = normal_area / twice_area;
  const double d = (s - a).dot(n);
  const double ad = std::abs(d);
  const Vec3 corner[3] = {a - s, b - s, c - s};
  const double r[3] = {corner[0].norm(), corner[1].norm(), corner[2].norm()};
  double sum_log = 0;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const Vec3 edge = corner[j] - corner[i];
    const double edge_length = edge.norm();
    if (edge_length == 0) continue;
    const Vec3 t = edge / edge_length;
    const double P0 = corner[i].dot(t.cross(n));
    const double l_minus = corner[i].dot(t), l_plus = corner[j].dot(t);
    const double R0sq = P0 * P0 + d * d;
    if (P0 == 0 || R0sq <= 1e-24 * edge_length * edge_length) continue;
    double arg;
    if (l_minus >= 0) arg = (r[j] + l_plus) / (r[i] + l_minus);
    else if (l_plus <= 0) arg = (r[i] - l_minus) / (r[j] - l_plus);
    else arg = (r[j] + l_plus) * (r[i] - l_minus) / R0sq;
    sum_log += P0 * std::log(arg);
  }
  if (ad == 0) return sum_log;
  const double den = r[0] * r[1] * r[2] + corner[0].dot(corner[1]) * r[2] + corner[0].dot(corner[2]) * r[1] +
                     corner[1].dot(corner[2]) * r[0];
  return sum_log - ad * 2 * std::atan2(ad * twice_area, den);
}
}
namespace pre_ {
struct Tri {
  Vec3 a, b, c, n; double twice_area = 0; Vec3 t[3], m[3]; double len[3];
  Tri(const Vec3& a_, const Vec3& b_, const Vec3& c_) : a(a_), b(b_), c(c_) {
    const Vec3 na = (b - a).cross(c - a); twice_area = na.norm(); n = twice_area > 0 ? Vec3(na / twice_area) : Vec3::Zero();
    const Vec3 p[3] = {a, b, c};
    for (int i = 0; i < 3; ++i) { const Vec3 e = p[(i + 1) % 3] - p[i]; len[i] = e.norm(); t[i] = len[i] > 0 ? Vec3(e / len[i]) : Vec3::Zero(); m[i] = t[i].cross(n); }
  }
  double operator()(const Vec3& s) const {
    if (twice_area == 0) return 0;
    const double d = (s - a).dot(n);
    const double ad = std::abs(d);
    const Vec3 corner[3] = {a - s, b - s, c - s};
    const double r[3] = {corner[0].norm(), corner[1].norm(), corner[2].norm()};
    double sum_log = 0;
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      if (len[i] == 0) continue;
      const double P0 = corner[i].dot(m[i]);
      const double l_minus = corner[i].dot(t[i]), l_plus = corner[j].dot(t[i]);
      const double R0sq = P0 * P0 + d * d;
      if (P0 == 0 || R0sq <= 1e-24 * len[i] * len[i]) continue;
      double arg;
      if (l_minus >= 0) arg = (r[j] + l_plus) / (r[i] + l_minus);
      else if (l_plus <= 0) arg = (r[i] - l_minus) / (r[j] - l_plus);
      else arg = (r[j] + l_plus) * (r[i] - l_minus) / R0sq;
      sum_log += P0 * std::log(arg);
    }
    if (ad == 0) return sum_log;
    const double den = r[0] * r[1] * r[2] + corner[0].dot(corner[1]) * r[2] + corner[0].dot(corner[2]) * r[1] + corner[1].dot(corner[2]) * r[0];
    return sum_log - ad * 2 * std::atan2(ad * twice_area, den);
  }
};
double triangle_potential(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& s) { return Tri(a,b,c)(s); }
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
    double o = old_::triangle_potential(a, b, c, s), n = new_::triangle_potential(a, b, c, s);
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
  auto [tn, an] = time(new_::triangle_potential);
  auto [to2, ao2] = time(old_::triangle_potential);
  auto [tn2, an2] = time(new_::triangle_potential);
  printf("old %.1f ns new %.1f ns | old %.1f new %.1f\n", to, tn, to2, tn2);
  std::vector<pre_::Tri> tris; for (auto& k : cases) tris.emplace_back(k[0], k[1], k[2]);
  auto t0 = std::chrono::steady_clock::now(); double acc = 0;
  for (int rep = 0; rep < 5; ++rep) for (size_t i = 0; i < cases.size(); ++i) acc += tris[i](cases[i][3]);
  printf("pre %.1f ns (%g vs %g)\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / (5 * cases.size()) * 1e9, acc, an);
}
