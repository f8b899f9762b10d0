// The exact triangle-triangle test against CGAL's do_intersect (Epick: exact predicates) on
// random and adversarial pairs, the orientation filters against CGAL's exact signs, and the
// common segment against the geometry it must lie on.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <catch2/catch.hpp>
#include <random>

#include "mtcs/mesh/exact_predicates.h"
#include "mtcs/mesh/triangle_intersection.h"
#include "support/random_draws.h"

using namespace mtcs;
using mesh::Triangle;
using geometry::Vec3;

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

K::Point_3 cgal(const Vec3& p) { return {p.x(), p.y(), p.z()}; }
K::Triangle_3 cgal(const Triangle& t) { return {cgal(t[0]), cgal(t[1]), cgal(t[2])}; }

bool degenerate(const Triangle& t) { return CGAL::collinear(cgal(t[0]), cgal(t[1]), cgal(t[2])); }

// Checks one pair in all 72 orders (swap, rotations, reflections) against CGAL; returns the
// number of disagreements.
int disagreements(const Triangle& a, const Triangle& b) {
  if (degenerate(a) || degenerate(b)) return 0;
  const bool want = CGAL::do_intersect(cgal(a), cgal(b));
  int bad = 0;
  static const int perms[6][3] = {{0, 1, 2}, {1, 2, 0}, {2, 0, 1}, {0, 2, 1}, {2, 1, 0}, {1, 0, 2}};
  for (const auto& pa : perms)
    for (const auto& pb : perms) {
      const Triangle x{a[pa[0]], a[pa[1]], a[pa[2]]}, y{b[pb[0]], b[pb[1]], b[pb[2]]};
      bad += mesh::triangles_intersect(x, y) != want;
      bad += mesh::triangles_intersect(y, x) != want;
    }
  return bad;
}

// A random rigid motion with irrational entries: the configuration keeps its incidences only
// approximately, which is what near-degenerate means.
Vec3 move(const Vec3& p, const Eigen::Matrix3d& r, const Vec3& t) { return r * p + t; }

}  // namespace

TEST_CASE("orientation filters agree with CGAL's exact signs", "[mesh][predicates]") {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> u(-1, 1);
  int undecided_by_float = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 a = mtcs_test::draw_vec3(u, rng), b = mtcs_test::draw_vec3(u, rng), c = mtcs_test::draw_vec3(u, rng);
    // d: near the plane of abc (rounded affine combination), or on a lattice of coplanar points.
    const double s = u(rng), t = u(rng);
    Vec3 d = a + s * (b - a) + t * (c - a);
    if (i % 3 == 0) d += mtcs_test::draw_vec3(u, rng) * 1e-17;
    const int want = int(CGAL::orientation(K::Point_3(a.x(), a.y(), a.z()), K::Point_3(b.x(), b.y(), b.z()),
                                           K::Point_3(c.x(), c.y(), c.z()), K::Point_3(d.x(), d.y(), d.z())));
    REQUIRE(mesh::orient3d(a, b, c, d) == want);
    const double fast = ((b - a).cross(c - a)).dot(d - a);
    undecided_by_float += (fast > 0) - (fast < 0) != want;
    const int want2 = int(CGAL::orientation(K::Point_2(a.x(), a.y()), K::Point_2(b.x(), b.y()), K::Point_2(d.x(), d.y())));
    REQUIRE(mesh::orient2d(a.x(), a.y(), b.x(), b.y(), d.x(), d.y()) == want2);
  }
  // The inputs are hard enough that the naive sign fails on some: the test can fail.
  CHECK(undecided_by_float > 0);
}

TEST_CASE("triangle-triangle: zero disagreement with CGAL on lattice pairs (coplanar, shared "
          "edges and corners, touching)", "[mesh][triangle]") {
  // Corners on a 3x3x3 lattice: coplanar overlapping and disjoint pairs, shared edges and
  // corners, edges on faces and corners on edges occur by the thousands.
  std::mt19937_64 rng(2);
  std::uniform_int_distribution<int> g(0, 2);
  auto corner = [&] { return mtcs_test::vec3_of([&] { return double(g(rng)); }); };
  int bad = 0, hits = 0, tested = 0;
  for (int i = 0; i < 20000; ++i) {
    const Triangle a{corner(), corner(), corner()}, b{corner(), corner(), corner()};
    if (degenerate(a) || degenerate(b)) continue;
    ++tested;
    hits += CGAL::do_intersect(cgal(a), cgal(b));
    bad += disagreements(a, b);
  }
  CHECK(bad == 0);
  CHECK(tested > 10000);
  CHECK(hits > tested / 5);
  CHECK(hits < tested * 4 / 5);
}

TEST_CASE("triangle-triangle: zero disagreement with CGAL on random and near-degenerate pairs", "[mesh][triangle]") {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  int bad = 0;
  for (int i = 0; i < 4000; ++i) {
    const Eigen::Matrix3d r = mtcs_test::draw_quaternion(u, rng).normalized().toRotationMatrix();
    const Vec3 t = mtcs_test::draw_vec3(u, rng) * 10;
    std::uniform_int_distribution<int> g(0, 2);
    auto corner = [&] { return move(mtcs_test::vec3_of([&] { return double(g(rng)); }), r, t); };
    // Lattice pairs after a rotation: incidences survive only up to rounding.
    const Triangle a{corner(), corner(), corner()}, b{corner(), corner(), corner()};
    bad += disagreements(a, b);
    // Random pairs at the scale of their size.
    const Triangle c{mtcs_test::draw_vec3(u, rng), mtcs_test::draw_vec3(u, rng), mtcs_test::draw_vec3(u, rng)};
    const Triangle d{mtcs_test::draw_vec3(u, rng), mtcs_test::draw_vec3(u, rng), mtcs_test::draw_vec3(u, rng)};
    bad += disagreements(c, d);
    // Nearly coplanar: d's corners pushed off c's plane by about one ulp.
    const Vec3 n = (c[1] - c[0]).cross(c[2] - c[0]).normalized();
    auto on_c = [&] { return c[0] + u(rng) * 1.5 * (c[1] - c[0]) + u(rng) * 1.5 * (c[2] - c[0]) + n * (u(rng) * 1e-16); };
    bad += disagreements(c, Triangle{on_c(), on_c(), on_c()});
    // A corner of one touching the other's face (rounded to double), the rest on one side.
    const Vec3 touch = c[0] + 0.3 * (c[1] - c[0]) + 0.3 * (c[2] - c[0]);
    bad += disagreements(c, Triangle{touch, touch + n + mtcs_test::draw_vec3(u, rng) * 0.3, touch + n * 0.5 + mtcs_test::draw_vec3(u, rng)});
    // An edge lying in the other's plane (up to rounding), crossing its boundary.
    const Vec3 e0 = c[0] + u(rng) * (c[1] - c[0]) + u(rng) * (c[2] - c[0]);
    const Vec3 e1 = c[0] + u(rng) * (c[1] - c[0]) + u(rng) * (c[2] - c[0]);
    bad += disagreements(c, Triangle{e0, e1, e0 + n * u(rng) + mtcs_test::draw_vec3(u, rng) * 0.2});
  }
  CHECK(bad == 0);
}

TEST_CASE("triangle-triangle: named configurations", "[mesh][triangle]") {
  const Triangle base{Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(0, 2, 0)};
  auto meets = [&](const Triangle& t) { return mesh::triangles_intersect(base, t); };
  CHECK(meets({Vec3(0.5, 0.5, 0), Vec3(3, 0.5, 0), Vec3(0.5, 3, 0)}));      // coplanar overlapping
  CHECK_FALSE(meets({Vec3(2, 2, 0), Vec3(3, 2, 0), Vec3(2, 3, 0)}));        // coplanar disjoint
  CHECK(meets({Vec3(1, 1, 0), Vec3(3, 1, 0), Vec3(1, 3, 0)}));              // coplanar, corner on edge
  CHECK(meets({Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, -1, 0)}));             // shared edge, coplanar
  CHECK(meets({Vec3(0, 0, 0), Vec3(2, 0, 0), Vec3(1, 0, 1)}));              // shared edge, folded
  CHECK(meets({Vec3(0, 0, 0), Vec3(-1, -1, 1), Vec3(-1, 0, 2)}));           // shared corner only
  CHECK(meets({Vec3(0.5, 0.5, 0), Vec3(0.5, 0.5, 1), Vec3(1, 0.2, 1)}));    // corner on the face
  CHECK(meets({Vec3(0.2, 0.2, 0), Vec3(1, 0.5, 0), Vec3(0.5, 0.5, 1)}));    // edge on the face
  CHECK_FALSE(meets({Vec3(0.5, 0.5, 1e-300), Vec3(0.5, 0.5, 1), Vec3(1, 0.2, 1)}));  // just above
  CHECK(meets({Vec3(0.5, 0.5, -1), Vec3(0.6, 0.5, 1), Vec3(0.5, 0.6, 1)}));  // piercing
  CHECK_FALSE(meets({Vec3(2, 2, -1), Vec3(2, 2, 1), Vec3(3, 3, 0)}));        // beside
}

TEST_CASE("triangle-triangle: the common segment lies on both triangles", "[mesh][triangle]") {
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(-1, 1);
  int checked = 0;
  for (int i = 0; i < 5000; ++i) {
    const Triangle a{mtcs_test::draw_vec3(u, rng), mtcs_test::draw_vec3(u, rng), mtcs_test::draw_vec3(u, rng)};
    const Triangle b{mtcs_test::draw_vec3(u, rng), mtcs_test::draw_vec3(u, rng), mtcs_test::draw_vec3(u, rng)};
    const auto r = mesh::intersect_triangles(a, b);
    const auto x = CGAL::intersection(cgal(a), cgal(b));
    REQUIRE(r.intersects == bool(x));
    if (!r.intersects) {
      CHECK(mesh::triangle_distance(a, b) > 0);
      continue;
    }
    // CGAL's construction of the common part: a point or a segment here (no coplanar pairs).
    Vec3 p, q;
    if (const auto* s = boost::get<K::Segment_3>(&*x)) {
      p = Vec3(s->source().x(), s->source().y(), s->source().z());
      q = Vec3(s->target().x(), s->target().y(), s->target().z());
    } else if (const auto* pt = boost::get<K::Point_3>(&*x)) {
      p = q = Vec3(pt->x(), pt->y(), pt->z());
    } else {
      continue;
    }
    const bool same = ((r.p - p).norm() < 1e-9 && (r.q - q).norm() < 1e-9) || ((r.p - q).norm() < 1e-9 && (r.q - p).norm() < 1e-9);
    CHECK(same);
    ++checked;
  }
  CHECK(checked > 500);
}

TEST_CASE("triangle distance: brute force over dense samples bounds it from above", "[mesh][triangle]") {
  const Triangle a{Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  const Triangle b{Vec3(0.2, 0.2, 0.5), Vec3(1.5, 0.2, 0.3), Vec3(0.2, 1.5, 0.9)};
  // Dense samples of both triangles: an upper bound, within a sample spacing of the distance.
  const double d = mesh::triangle_distance(a, b);
  double sampled = 1e9;
  for (int i = 0; i <= 60; ++i)
    for (int j = 0; i + j <= 60; ++j)
      for (int k = 0; k <= 60; ++k)
        for (int l = 0; k + l <= 60; ++l) {
          const Vec3 pa = a[0] + (a[1] - a[0]) * (i / 60.0) + (a[2] - a[0]) * (j / 60.0);
          const Vec3 pb = b[0] + (b[1] - b[0]) * (k / 60.0) + (b[2] - b[0]) * (l / 60.0);
          sampled = std::min(sampled, (pa - pb).norm());
        }
  CHECK(d <= sampled + 1e-15);
  CHECK(d > sampled - 0.05);
}
