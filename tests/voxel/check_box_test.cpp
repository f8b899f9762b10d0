// CheckBox against closed forms (gaps, touching faces, rim corners and edges, end caps),
// degenerate tools, and the geometry module's cylinder-box distance kernel (an independent
// method) on random poses away from contact.

#include <catch2/catch.hpp>
#include <random>

#include "mtcs/geometry/cylinder_box_distance.h"
#include "voxel/check_box.h"
#include "support/random_draws.h"

using namespace mtcs;
using namespace mtcs::voxel;

namespace {

bool meets(const Vec3& pivot, const Vec3& dir, const Tool& tool, const Box& box) {
  return CheckBox(pivot, dir, tool)(box).collision;
}

Box box(double x0, double y0, double z0, double x1, double y1, double z1) { return {Vec3(x0, y0, z0), Vec3(x1, y1, z1)}; }

}  // namespace

TEST_CASE("cylinder against a box at a known gap, touching and overlapping", "[voxel][checkbox]") {
  const Tool tool{{0, 10, 1}};  // along +z from the origin, radius 1, length 10
  const Vec3 up(0, 0, 1), o = Vec3::Zero();
  for (double gap : {1e-9, 1e-6, 0.5}) CHECK_FALSE(meets(o, up, tool, box(1 + gap, -1, 2, 3, 1, 3)));
  CHECK(meets(o, up, tool, box(1, -1, 2, 3, 1, 3)));          // touching the shell along a line
  CHECK(meets(o, up, tool, box(1 - 1e-9, -1, 2, 3, 1, 3)));   // overlapping
  CHECK(meets(o, up, tool, box(-0.1, -0.1, 2, 0.1, 0.1, 3)));  // around the axis
  CHECK(meets(o, up, tool, box(-5, -5, -5, 5, 5, 15)));         // the tool inside the box
  // End caps: the plane z = 10 and z = 0.
  CHECK(meets(o, up, tool, box(-0.5, -0.5, 10, 0.5, 0.5, 11)));
  CHECK_FALSE(meets(o, up, tool, box(-0.5, -0.5, 10 + 1e-9, 0.5, 0.5, 11)));
  CHECK(meets(o, up, tool, box(-0.5, -0.5, -1, 0.5, 0.5, 0)));
  CHECK_FALSE(meets(o, up, tool, box(-0.5, -0.5, -1, 0.5, 0.5, -1e-9)));
  // The same pair exactly touching through an undecided verdict reports a collision.
  const BoxVerdict touch = CheckBox(o, up, tool)(box(1, -1, 2, 3, 1, 3));
  CHECK(touch.collision);
}

TEST_CASE("corner and edge contacts with the shell and the rims", "[voxel][checkbox]") {
  const Tool tool{{0, 10, 5}};
  const Vec3 up(0, 0, 1), o = Vec3::Zero();
  // A vertical box edge at (3, 4): distance 5 from the axis, exactly on the shell.
  CHECK(meets(o, up, tool, box(3, 4, 2, 4, 5, 3)));
  CHECK_FALSE(meets(o, up, tool, box(3 + 1e-9, 4, 2, 4, 5, 3)));
  // A box corner (3, 4, 10) on the rim of the far end disk.
  CHECK(meets(o, up, tool, box(3, 4, 10, 4, 5, 11)));
  CHECK_FALSE(meets(o, up, tool, box(3, 4, 10 + 1e-9, 4, 5, 11)));
  CHECK_FALSE(meets(o, up, tool, box(3, 4 + 1e-9, 10, 4, 5, 11)));
  // A horizontal box edge (y = 5, z = 10) tangent to the far rim at (0, 5, 10).
  CHECK(meets(o, up, tool, box(-1, 5, 10, 1, 6, 11)));
  CHECK_FALSE(meets(o, up, tool, box(-1, 5 + 1e-9, 10, 1, 6, 11)));
  // Tilted axis (0, 3, 4)/5 from the pivot: the far disk centre is (0, 6, 8) for length 10;
  // a point 5 beyond it along the axis is outside, a box containing the centre collides.
  const Vec3 tilted(0, 3, 4);
  CHECK(meets(o, tilted, tool, box(-0.1, 5.9, 7.9, 0.1, 6.1, 8.1)));
  CHECK_FALSE(meets(o, tilted, tool, box(-0.1, 8.9, 11.9, 0.1, 9.1, 12.1)));
  // A box beside the shell: its nearest point at distance 5 + 1e-6 from the axis, 3 along it.
  const Vec3 axis = tilted / 5, side(0, 0.8, -0.6);  // unit normal to the axis
  const Vec3 near = 3 * axis + (5 + 1e-6) * side;
  CHECK_FALSE(meets(o, tilted, tool, {near - Vec3(0.1, 0, 0), near + Vec3(0.1, 0, 0)}));
  const Vec3 inside = 3 * axis + (5 - 1e-6) * side;
  CHECK(meets(o, tilted, tool, {inside - Vec3(0.1, 0, 0), inside + Vec3(0.1, 0, 0)}));
}

TEST_CASE("degenerate tools: radius 0 and length 0", "[voxel][checkbox]") {
  const Vec3 up(0, 0, 1), o = Vec3::Zero();
  const Tool segment{{0, 10, 0}};
  CHECK(meets(o, up, segment, box(0, 0, 5, 1, 1, 6)));  // touches the axis along an edge
  CHECK_FALSE(meets(o, up, segment, box(1e-9, 0, 5, 1, 1, 6)));
  const Tool disk{{4, 4, 2}};
  CHECK(meets(o, up, disk, box(2, -1, 4, 3, 1, 5)));    // rim touches the face x = 2 at z = 4
  CHECK_FALSE(meets(o, up, disk, box(-1, -1, 4 + 1e-9, 1, 1, 5)));
  CHECK_FALSE(meets(o, up, disk, box(2 + 1e-9, -1, 3, 3, 1, 5)));
  const Tool point{{3, 3, 0}};
  CHECK(meets(o, up, point, box(0, 0, 3, 1, 1, 4)));
  CHECK_FALSE(meets(o, up, point, box(0, 0, 3 + 1e-9, 1, 1, 4)));
}

TEST_CASE("CheckBox agrees with the cylinder-box distance kernel away from contact", "[voxel][checkbox]") {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> U(-1, 1), R(0, 3);
  int far = 0, deep = 0;
  for (int n = 0; n < 20000; ++n) {
    const Vec3 pivot = mtcs_test::draw_vec3(U, rng), dir = mtcs_test::draw_vec3(U, rng);
    if (dir.norm() < 0.1) continue;
    const double a = R(rng), len = R(rng) * 2, r = R(rng);
    const Tool tool{{a, a + len, r}};
    const Vec3 lo = 3 * mtcs_test::draw_vec3(U, rng);
    const Box b{lo, lo + mtcs_test::draw_vec3(R, rng)};
    const Vec3 u = dir.normalized();
    const geometry::Cylinder cyl{pivot + a * u, pivot + (a + len) * u, r};
    const double dist = geometry::distance(cyl, b).distance;
    // Shrunk by 1e-7 and still touching: a collision with margin.
    const Box shrunk{b.min + Vec3::Constant(1e-7), b.max - Vec3::Constant(1e-7)};
    const bool deep_hit = (shrunk.min.array() < shrunk.max.array()).all() && geometry::distance(cyl, shrunk).distance == 0;
    const BoxVerdict v = CheckBox(pivot, dir, tool)(b);
    if (dist > 1e-7) {
      ++far;
      REQUIRE_FALSE(v.collision);
    } else if (deep_hit) {
      ++deep;
      REQUIRE(v.collision);
    }
    REQUIRE(v.precision != Precision::undecided);
  }
  CHECK(far > 3000);
  CHECK(deep > 3000);
}
