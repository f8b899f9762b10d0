// The line-sink kernels against closed forms and brute-force quadrature.
#include <catch2/catch.hpp>

#include <cmath>

#include "thermal/kernels/segment_potential.h"
#include "thermal/kernels/line_sink_fields.h"
#include <chrono>
#include <random>
#include <vector>
#include <cstdio>
#include "support/random_draws.h"

using namespace mtcs::thermal;

namespace {

// Composite Gauss-Legendre (5 points) over n panels of the segment: the independent check.
template <class F>
double integrate_segment(const Vec3& a, const Vec3& b, int panels, F&& f) {
  static const double x[5] = {-0.9061798459386640, -0.5384693101056831, 0.0, 0.5384693101056831,
                              0.9061798459386640};
  static const double w[5] = {0.2369268850561891, 0.4786286704993665, 0.5688888888888889,
                              0.4786286704993665, 0.2369268850561891};
  const double L = (b - a).norm();
  double sum = 0;
  for (int p = 0; p < panels; ++p)
    for (int g = 0; g < 5; ++g) {
      const double t = (p + 0.5 + 0.5 * x[g]) / panels;
      sum += w[g] * 0.5 / panels * f(a + t * (b - a));
    }
  return sum * L;
}

// Midpoint rule on n x n sub-triangles (4^k refinement by barycentric grid).
double integrate_triangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& s, int n) {
  const double area = 0.5 * (b - a).cross(c - a).norm();
  double sum = 0;
  // Upward and downward sub-triangles of the barycentric grid, each sampled at 3 interior points.
  auto tri = [&](const Vec3& p, const Vec3& q, const Vec3& r) {
    const Vec3 m1 = (4 * p + q + r) / 6, m2 = (p + 4 * q + r) / 6, m3 = (p + q + 4 * r) / 6;
    return ((s - m1).norm() > 0 ? 1 / (s - m1).norm() : 0) +
           ((s - m2).norm() > 0 ? 1 / (s - m2).norm() : 0) +
           ((s - m3).norm() > 0 ? 1 / (s - m3).norm() : 0);
  };
  auto at = [&](int i, int j) { return a + (double(i) / n) * (b - a) + (double(j) / n) * (c - a); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; i + j < n; ++j) {
      sum += tri(at(i, j), at(i + 1, j), at(i, j + 1));
      if (i + j + 1 < n) sum += tri(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
    }
  return sum / 3 * area / (double(n) * n);
}

}  // namespace

TEST_CASE("segment potential opposite the midpoint equals 2 asinh(L/2 rho) for any rho") {
  const Vec3 a(-500, 0, 0), b(500, 0, 0);
  for (double rho : {10.0, 1.0, 1e-3, 1e-5, 1e-7, 1e-9}) {
    const double exact = 2 * std::asinh(500 / rho);
    CHECK(segment_potential(a, b, Vec3(0, rho, 0)) == Approx(exact).epsilon(1e-14));
  }
}

TEST_CASE("segment potential keeps its precision far from the origin") {
  const Vec3 offset(1e4, -1e4, 1e4);
  const Vec3 a(0, 0, 0), b(0, 0, 1e6);  // aspect ratio 1e6 against a 1 mm bore
  const Vec3 s(0.5, 0, 3e5);
  const double exact = std::asinh(3e5 / 0.5) + std::asinh(7e5 / 0.5);
  CHECK(segment_potential(a, b, s) == Approx(exact).epsilon(1e-14));
  // Offsetting moves the inputs by 1e4: the relative error of the offset, 1e-16 * 1e4 / 0.5.
  CHECK(segment_potential(a + offset, b + offset, s + offset) == Approx(exact).epsilon(1e-10));
}

TEST_CASE("segment potential and dipole factor match quadrature beyond the ends and beside") {
  const Vec3 a(1, 2, 3), b(4, -1, 7);
  const Vec3 points[] = {Vec3(9, 5, -2), Vec3(2.5, 0.5, 5) + Vec3(0.3, 0.1, -0.2),
                         b + 2.0 * (b - a) + Vec3(0, 1e-3, 0), a - 0.5 * (b - a),
                         Vec3(-20, 30, 11)};
  for (const Vec3& s : points) {
    const SegmentField f = segment_field(a, b, s);
    const double phi = integrate_segment(a, b, 2000, [&](const Vec3& y) { return 1 / (s - y).norm(); });
    CHECK(f.phi == Approx(phi).epsilon(1e-9));
    // A transverse unit moment: the dipole integral by quadrature.
    const Vec3 p = (b - a).unitOrthogonal();
    const double dip = integrate_segment(a, b, 2000, [&](const Vec3& y) {
      return (s - y).dot(p) / std::pow((s - y).norm(), 3);
    });
    CHECK(f.dipole_factor * p.dot(f.rho) == Approx(dip).epsilon(1e-8).margin(1e-14));
  }
}

TEST_CASE("dipole factor on the axis beyond an end stays finite and exact") {
  // On the axis the transverse offset is zero, but the factor must not be 0/0:
  // (t_a/r_a - t_b/r_b) / rho^2 -> (1/t_b^2 - 1/t_a^2) / 2 as rho -> 0.
  const Vec3 a(0, 0, 0), b(10, 0, 0);
  const SegmentField f = segment_field(a, b, Vec3(15, 1e-9, 0));
  CHECK(std::isfinite(f.dipole_factor));
  CHECK(f.dipole_factor == Approx(0.5 * (1 / 25.0 - 1 / 225.0)).epsilon(1e-9));
  const SegmentField g = segment_field(a, b, Vec3(-5, 0, 0));
  CHECK(g.dipole_factor == Approx(0.5 * (1 / 25.0 - 1 / 225.0)).epsilon(1e-12));
}

TEST_CASE("triangle potential matches quadrature off, in and on its plane") {
  const Vec3 a(0, 0, 0), b(4, 0.5, 0.2), c(1, 3, -0.4);
  const Vec3 n = (b - a).cross(c - a).normalized();
  const Vec3 centroid = (a + b + c) / 3;
  struct Case { Vec3 s; double tol; };
  const Case cases[] = {
      {centroid + 2.0 * n, 1e-6},            // above
      {centroid - 0.3 * n, 1e-4},            // close below
      {Vec3(10, -7, 5), 1e-7},               // far
      {a + 1.5 * (b - a) + 0.0 * n, 1e-5},   // in the plane, beyond an edge line
      {2.0 * c - centroid, 1e-5},            // in the plane, outside
      {centroid, 2e-3},                      // on the triangle: integrable singularity
      {0.5 * (a + b), 2e-3},                 // on an edge
  };
  for (const Case& k : cases) {
    const double quad = integrate_triangle(a, b, c, k.s, 400);
    CHECK(triangle_potential(a, b, c, k.s) == Approx(quad).epsilon(k.tol));
    CHECK(std::isfinite(triangle_potential(a, b, c, k.s)));
  }
}

TEST_CASE("triangle potential at its own corners is finite and continuous (NaN at cavity corners)") {
  // The defect: a sample on a corner of a heated triangle, exactly or through an image's mirror
  // and back, gave inf or NaN (log(x / 0) on the two edges that meet there), and with it the
  // cavity field of mtcs thermal at the box cavity's corners.
  int non_finite = 0;
  for (int k = 0; k < 200; ++k) {
    const double x = 50 + 0.37 * k;
    const Vec3 a(x, 25.3, 105.1), b(x + 0.7, 175.9, 105.3), c(x + 0.2, 175.1, 108.7);
    for (const Vec3& q : {a, b, c}) {
      const Vec3 mirror(-1, 1, 1), offset(600.2, 0, 0);
      const Vec3 s = mirror.cwiseProduct(mirror.cwiseProduct(q) + offset) + offset;
      for (const Vec3& p : {q, s}) {
        const double v = triangle_potential(a, b, c, p);
        if (!std::isfinite(v)) ++non_finite;
        // The potential is continuous: a point 1e-7 mm inside the triangle from the corner.
        const Vec3 inside = p + 1e-7 * ((a + b + c) / 3 - p).normalized();
        if (k % 50 == 0) CHECK(v == Approx(triangle_potential(a, b, c, inside)).epsilon(1e-6));
      }
    }
  }
  CHECK(non_finite == 0);
  // And the corner's value against quadrature.
  const Vec3 a(0, 0, 0), b(4, 0.5, 0.2), c(1, 3, -0.4);
  CHECK(triangle_potential(a, b, c, b) == Approx(integrate_triangle(a, b, c, b, 400)).epsilon(2e-3));
}

TEST_CASE("triangle potential: a square's centre, the closed form 8 a asinh(1)") {
  // Unit density on the square [-a,a]^2 at its centre: 8 a asinh(1); two triangles.
  const double h = 3;
  const Vec3 p00(-h, -h, 0), p10(h, -h, 0), p11(h, h, 0), p01(-h, h, 0);
  const Vec3 o(0, 0, 0);
  const double sum = triangle_potential(p00, p10, p11, o) + triangle_potential(p00, p11, p01, o);
  CHECK(sum == Approx(8 * h * std::asinh(1.0)).epsilon(1e-13));
  // At height z above the centre of the square (Durand): far away it tends to area / z.
  const Vec3 far(0, 0, 1e5);
  const double sum_far = triangle_potential(p00, p10, p11, far) + triangle_potential(p00, p11, p01, far);
  CHECK(sum_far == Approx(36.0 / 1e5).epsilon(1e-8));
  // Orientation does not matter for a potential.
  CHECK(triangle_potential(p00, p11, p10, Vec3(1, 2, 0.5)) ==
        Approx(triangle_potential(p00, p10, p11, Vec3(1, 2, 0.5))).epsilon(1e-14));
}

// Wilton's form with the solid angle as two atans per edge (the kernel's form before 2026-11-29):
// an independent check of the single atan2 (Van Oosterom & Strackee) the kernel takes now.
double triangle_potential_per_edge(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& s) {
  const Vec3 normal_area = (b - a).cross(c - a);
  const Vec3 n = normal_area.normalized();
  const double d = (s - a).dot(n), ad = std::abs(d);
  const Vec3 p = s - d * n;
  const Vec3 corners[3] = {a, b, c};
  double sum_log = 0, sum_angle = 0;
  for (int i = 0; i < 3; ++i) {
    const Vec3 &p0 = corners[i], &p1 = corners[(i + 1) % 3];
    const Vec3 t = (p1 - p0).normalized(), m = t.cross(n);
    const double P0 = (p0 - p).dot(m), l_minus = (p0 - p).dot(t), l_plus = (p1 - p).dot(t);
    const double R0sq = P0 * P0 + d * d, R_minus = (s - p0).norm(), R_plus = (s - p1).norm();
    if (R0sq <= 1e-24 * (p1 - p0).squaredNorm() || P0 == 0) continue;
    const double R0 = std::sqrt(R0sq);
    double lg;
    if (l_minus >= 0) lg = std::log((R_plus + l_plus) / (R_minus + l_minus));
    else if (l_plus <= 0) lg = std::log((R_minus - l_minus) / (R_plus - l_plus));
    else lg = std::asinh(l_plus / R0) - std::asinh(l_minus / R0);
    sum_log += P0 * lg;
    if (ad != 0)
      sum_angle += std::atan(P0 * l_plus / (R0sq + ad * R_plus)) - std::atan(P0 * l_minus / (R0sq + ad * R_minus));
  }
  return sum_log - ad * sum_angle;
}

TEST_CASE("triangle potential: the one-atan2 solid angle against two atans per edge") {
  // Random triangles and points: above, 1e-9 off the plane, near an edge's line, far, offset by
  // 1e4; sizes over six decades. Both forms agree to 1e-7 relative at worst (near an edge's line,
  // where both lose the same digits), 1e-12 typically.
  std::mt19937_64 rng(20261129);
  std::uniform_real_distribution<double> u(-1, 1);
  double worst = 0;
  std::vector<double> errors;
  for (int k = 0; k < 20000; ++k) {
    const Vec3 flat(1, 1, 0.1);
    Vec3 a = mtcs_test::draw_vec3(u, rng).cwiseProduct(flat), b = mtcs_test::draw_vec3(u, rng).cwiseProduct(flat),
         c = mtcs_test::draw_vec3(u, rng).cwiseProduct(flat);
    Vec3 s = mtcs_test::draw_vec3(u, rng);
    const Vec3 n = (b - a).cross(c - a).normalized();
    switch (k % 5) {
      case 1: s -= (s - a).dot(n) * n - 1e-9 * u(rng) * n; break;     // in the plane, nearly
      case 2: s = a + (b - a) * (0.5 + u(rng)) + 1e-6 * u(rng) * n; break;  // near an edge's line
      case 3: s *= 100; break;
      case 4: for (Vec3* v : {&a, &b, &c, &s}) *v += Vec3(1e4, -3e3, 50); break;
    }
    const double scale = std::pow(10.0, 3 * u(rng));
    a *= scale, b *= scale, c *= scale, s *= scale;
    const double mine = triangle_potential(a, b, c, s), ref = triangle_potential_per_edge(a, b, c, s);
    REQUIRE(std::isfinite(mine));
    const double e = std::abs(mine - ref) / std::abs(ref);
    worst = std::max(worst, e);
    errors.push_back(e);
  }
  std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
  CHECK(worst < 3e-7);
  CHECK(errors[errors.size() / 2] < 1e-13);
}

// The far expansion (element_fields_float with FarChunks) against the double closed forms: at
// points whose distance from every element's centre is h / q or more, q up to the ratio, the
// error stays inside the stated bound (sink q^8/9, dipole 5 q^8, over 1 - q^2) plus float
// rounding; and a chunk nearer than that keeps the closed forms (same values as without far).
TEST_CASE("element fields: the far expansion keeps its stated error bound") {
  Channel ch;
  ch.axis = {Vec3(10, 40, 45), Vec3(130, 35, 47)};
  ch.radius = 5;
  const int m = 4;
  const ChannelAxis axis = channel_axis(ch, m);
  const double h = 0.5 * axis.element_length;
  const Vec3 origin(60, 40, 30);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const double ratio : {0.2, 0.3, 0.35, 0.4}) {
    // Points around the channel at distances where the nearest element centre is h / ratio.. 3 h / ratio.
    std::vector<Vec3> pts;
    while (pts.size() < 2000) {
      const Vec3 p = axis.p0 + 0.5 * axis.length * axis.u + mtcs_test::draw_vec3(u, rng) * (4 * h / ratio + 0.5 * axis.length);
      double dmin = 1e300;
      for (int e = 0; e < m; ++e) dmin = std::min(dmin, (p - (axis.p0 + (e + 0.5) * axis.element_length * axis.u)).norm());
      if (dmin >= h / ratio * 1.001 && dmin <= 3 * h / ratio) pts.push_back(p);
    }
    const std::size_t T = pts.size();
    std::vector<float> x(T), y(T), z(T), w(T, 1.0f), box;
    for (std::size_t i = 0; i < T; ++i) {
      const Vec3 r = pts[i] - origin;
      x[i] = float(r.x()), y[i] = float(r.y()), z[i] = float(r.z());
      box.insert(box.end(), {x[i], y[i], z[i], x[i], y[i], z[i]});  // one target per chunk
    }
    const FarChunks far{box.data(), 1, float(ratio)};
    std::vector<float> out(T * 3 * m, 0.0f);
    element_fields_float_slots(axis, origin, 3, x.data(), y.data(), z.data(), w.data(), T, 1, out.data(), &far);
    const double q8 = std::pow(ratio, 8) / (1 - ratio * ratio);
    double worst_sink = 0, worst_dip = 0;
    for (std::size_t i = 0; i < T; ++i) {
      double phi[m], d1[m], d2[m];
      element_fields(axis, pts[i], phi, d1, d2);
      for (int e = 0; e < m; ++e) {
        worst_sink = std::max(worst_sink, std::abs(out[(e * 3) * T + i] - phi[e]) / phi[e]);
        // The dipole relative to its size at the point (|factor| |rho|).
        const double scale = std::hypot(d1[e], d2[e]) + 1e-30;
        worst_dip = std::max(worst_dip, std::hypot(out[(e * 3 + 1) * T + i] - d1[e], out[(e * 3 + 2) * T + i] - d2[e]) / scale);
      }
    }
    INFO("ratio " << ratio << " sink " << worst_sink << " dipole " << worst_dip);
    CHECK(worst_sink <= q8 / 9 + 2e-6);
    CHECK(worst_dip <= 5 * q8 + 2e-6);
    CHECK(worst_sink > 0);  // the expansion ran (not the closed forms)
  }
  // A chunk that reaches nearer than h / ratio: the closed forms, bit for bit.
  const Vec3 near_point = axis.p0 + 0.3 * axis.length * axis.u + Vec3(0, 0, 20);
  const float px = float(near_point.x() - 60), py = float(near_point.y() - 40), pz = float(near_point.z() - 30);
  const float wt = 1, box[6] = {px, py, pz, px, py, pz};
  const FarChunks far{box, 1, 0.3f};
  std::vector<float> a(3 * m, 0.0f), b(3 * m, 0.0f);
  element_fields_float_slots(axis, origin, 3, &px, &py, &pz, &wt, 1, 1, a.data(), &far);
  element_fields_float_slots(axis, origin, 3, &px, &py, &pz, &wt, 1, 1, b.data());
  CHECK(a == b);
}

TEST_CASE("triangle source: the gradient is the potential's derivative, principal value on the triangle") {
  const Vec3 a(1, 2, 3), b(7, 2.5, 3.5), c(2, 6, 2);
  const TriangleSource t(a, b, c);
  const Vec3 centroid = (a + b + c) / 3;
  // Above and below, near an edge's line, beyond a corner, far: central differences of the
  // closed-form potential (a second method) to 1e-6 of the gradient's size.
  const std::vector<Vec3> points{centroid + 0.5 * t.normal(), centroid - 0.01 * t.normal(),
                                 0.5 * (a + b) + Vec3(0.01, -0.3, 0.2), c + Vec3(0.5, 0.5, 0.5),
                                 Vec3(40, -30, 25), 0.5 * (a + b) + 0.05 * t.normal()};
  for (const Vec3& p : points) {
    const double h = 1e-5;
    Vec3 fd;
    for (int k = 0; k < 3; ++k) {
      const Vec3 e = Vec3::Unit(k) * h;
      fd[k] = (t.potential(p + e) - t.potential(p - e)) / (2 * h);
    }
    const Vec3 g = t.gradient(p);
    INFO("at " << p.transpose() << ": " << g.transpose() << " against " << fd.transpose());
    CHECK((g - fd).norm() <= 1e-6 * fd.norm() + 1e-9);
  }
  // Just above and below the centroid the normal parts are -+2 pi (the sheet's jump); on it,
  // the principal value: no normal part, the in-plane part continuous.
  const Vec3 above = t.gradient(centroid + 1e-9 * t.normal()), below = t.gradient(centroid - 1e-9 * t.normal());
  const Vec3 on = t.gradient(centroid);
  CHECK(above.dot(t.normal()) == Approx(-2 * M_PI).epsilon(1e-6));
  CHECK(below.dot(t.normal()) == Approx(2 * M_PI).epsilon(1e-6));
  CHECK(std::abs(on.dot(t.normal())) < 1e-12);
  CHECK((on - 0.5 * (above + below)).norm() < 1e-6);
}
