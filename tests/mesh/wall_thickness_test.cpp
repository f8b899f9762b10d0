// The part's local wall thickness (mesh/wall_thickness.h) against closed forms: a slab's distance
// across, the ball near a side face, a sphere's diameter, and the bundled cup's 2.5 mm shell.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mtcs/mesh/mesh_io.h"
#include "mtcs/mesh/wall_thickness.h"
#include "support/paths.h"

using namespace mtcs;
using geometry::Vec3;

namespace {

// A closed latitude-longitude sphere, outward-oriented.
mesh::TriangleMesh sphere(double radius, int rings, int segments) {
  mesh::TriangleMesh m;
  m.vertices.push_back({0, 0, radius});
  for (int i = 1; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const double th = std::numbers::pi * i / rings, ph = 2 * std::numbers::pi * j / segments;
      m.vertices.push_back(radius * Vec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th)));
    }
  m.vertices.push_back({0, 0, -radius});
  const int south = int(m.vertices.size()) - 1;
  const auto at = [&](int ring, int j) { return 1 + (ring - 1) * segments + (j % segments); };
  for (int j = 0; j < segments; ++j) {
    m.triangles.push_back({0, at(1, j), at(1, j + 1)});
    for (int i = 1; i + 1 < rings; ++i) {
      m.triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
    m.triangles.push_back({south, at(rings - 1, j + 1), at(rings - 1, j)});
  }
  return m;
}

}  // namespace

TEST_CASE("wall thickness: a slab is its distance across, less near a side face", "[mesh][thickness]") {
  const mesh::TriangleBvh slab(mesh::box_mesh({Vec3(0, 0, 0), Vec3(40, 30, 4)}));
  const Vec3 up(0, 0, 1);
  CHECK(mesh::inscribed_diameter(slab, Vec3(20, 15, 4), up, 100) == Approx(4).epsilon(1e-9));
  CHECK(mesh::inscribed_diameter(slab, Vec3(20, 15, 0), -up, 100) == Approx(4).epsilon(1e-9));
  // d from the side face x = 0: the ball of radius r centred above p fits while 0.99 r <= d.
  for (const double d : {0.5, 1.0, 1.5, 3.0}) {
    INFO("d = " << d);
    CHECK(mesh::inscribed_diameter(slab, Vec3(d, 15, 4), up, 100) == Approx(std::min(4.0, 2 * d / 0.99)).epsilon(2e-4));
  }
  CHECK(mesh::inscribed_diameter(slab, Vec3(20, 15, 4), up, 3) == Approx(3));  // capped
}

TEST_CASE("wall thickness: a sphere's is its diameter", "[mesh][thickness]") {
  const double radius = 10;
  const mesh::TriangleMesh m = sphere(radius, 48, 96);
  REQUIRE(mesh::closed_mesh_problem(m).empty());
  const mesh::TriangleBvh part(m);
  for (std::size_t t = 0; t < m.triangles.size(); t += 97) {
    const Vec3 a = m.corner(t, 0), b = m.corner(t, 1), c = m.corner(t, 2);
    const Vec3 p = (a + b + c) / 3, n = (b - a).cross(c - a).normalized();
    INFO("triangle " << t << " at " << p.transpose());
    // A facet's centroid lies up to ~0.07 mm inside the sphere, the facet across as much: the
    // faceted sphere's own diameter there.
    CHECK(mesh::inscribed_diameter(part, p, n, 100) == Approx(2 * radius).margin(0.2));
  }
}

TEST_CASE("wall thickness: the bundled cup's shell is 2.5 mm, its corners up to 1.27 times that", "[mesh][thickness]") {
  // A box-shaped cup, outside [50, 170] x [50, 130] x [40, 80] mm, walls and bottom 2.5 mm.
  const mesh::TriangleMesh cup = mesh::read_mesh(MTCS_SOURCE_DIR + "/molds/meshes/cup.off");
  const mesh::TriangleBvh part(cup);
  CHECK(mesh::inscribed_diameter(part, Vec3(110, 90, 40), Vec3(0, 0, -1), 100) == Approx(2.5).epsilon(1e-9));
  CHECK(mesh::inscribed_diameter(part, Vec3(110, 90, 42.5), Vec3(0, 0, 1), 100) == Approx(2.5).epsilon(1e-9));
  CHECK(mesh::inscribed_diameter(part, Vec3(50, 90, 60), Vec3(-1, 0, 0), 100) == Approx(2.5).epsilon(1e-9));
  CHECK(mesh::inscribed_diameter(part, Vec3(52.5, 90, 60), Vec3(1, 0, 0), 100) == Approx(2.5).epsilon(1e-9));
  // Every triangle's centroid: thicker than a fraction of the wall near edges, never thicker
  // than the largest ball where three walls meet, sqrt(3) s / (1 + sqrt(3)) in radius.
  const double corner = 2 * std::sqrt(3.0) * 2.5 / (1 + std::sqrt(3.0));
  for (std::size_t t = 0; t < cup.triangles.size(); ++t) {
    const Vec3 a = cup.corner(t, 0), b = cup.corner(t, 1), c = cup.corner(t, 2);
    const Vec3 p = (a + b + c) / 3, n = (b - a).cross(c - a).normalized();
    const double s = mesh::inscribed_diameter(part, p, n, 100);
    INFO("triangle " << t << " at " << p.transpose());
    CHECK(s > 0.5);
    CHECK(s <= corner / 0.99 + 1e-9);
  }
}

TEST_CASE("wall thickness: an open surface has none", "[mesh][thickness]") {
  mesh::TriangleMesh open;
  open.vertices = {Vec3(0, 0, 0), Vec3(10, 0, 0), Vec3(0, 10, 0)};
  open.triangles = {{0, 1, 2}};
  const mesh::TriangleBvh part(open);
  CHECK(mesh::inscribed_diameter(part, Vec3(2, 2, 0), Vec3(0, 0, 1), 100) == 0);
}
