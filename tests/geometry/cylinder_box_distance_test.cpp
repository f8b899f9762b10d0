// Solid cylinder vs solid box against closed forms, where a capsule (axis distance minus radius)
// is wrong, and against the same box as a closed mesh through the BVH query.

#include <catch2/catch.hpp>
#include <random>

#include "mtcs/geometry/cylinder_box_distance.h"
#include "mtcs/mesh/bvh.h"

using namespace mtcs::geometry;

TEST_CASE("cylinder vs box: closed forms", "[geometry][box]") {
  const Box box{{0, 0, 0}, {10, 20, 30}};
  // Parallel to the face x = 10 at a gap of 1.5 (axis at x = 13.5, radius 2).
  CHECK(distance(Cylinder{{13.5, 5, 5}, {13.5, 5, 25}, 2}, box).distance == Approx(1.5).epsilon(1e-14));
  // A flat end facing the face z = 30 from 0.25 above: 0.25 (a capsule says 0.25 - 2 < 0).
  CHECK(distance(Cylinder{{5, 10, 30.25}, {5, 10, 50}, 2}, box).distance == Approx(0.25).epsilon(1e-14));
  // The rim beside the edge x = 10, z = 30: end disk at z = 31, axis at x = 14 -> rim at x = 12:
  // nearest points (12, y, 31) and (10, y, 30): sqrt(4 + 1).
  CHECK(distance(Cylinder{{14, 10, 31}, {14, 10, 40}, 2}, box).distance == Approx(std::sqrt(5.0)).epsilon(1e-14));
  // Crossing a face, and wholly inside: 0.
  CHECK(distance(Cylinder{{5, 10, 25}, {5, 10, 35}, 1}, box).distance == 0);
  CHECK(distance(Cylinder{{5, 10, 10}, {5, 10, 20}, 1}, box).distance == 0);
  // The upper bound: a proven lower bound at or above it.
  const auto far = distance(Cylinder{{13.5, 5, 5}, {13.5, 5, 25}, 2}, box, {.upper_bound = 1.0});
  CHECK(far.bounded);
  CHECK(far.distance >= 1.0);
}

TEST_CASE("cylinder vs box: the box as a closed mesh agrees", "[geometry][box]") {
  const Box box{{-1, -2, -3}, {4, 5, 6}};
  const mtcs::mesh::TriangleBvh bvh(mtcs::mesh::box_mesh(box));
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> coord(-12, 12), radius(0.05, 3);
  for (int i = 0; i < 2000; ++i) {
    const Cylinder c{{coord(rng), coord(rng), coord(rng)}, {coord(rng), coord(rng), coord(rng)}, radius(rng)};
    const double ours = distance(c, box).distance;
    const auto mesh = mtcs::mesh::cylinder_clearance(bvh, c, std::numeric_limits<double>::infinity());
    INFO("case " << i);
    CHECK(ours == Approx(mesh.distance).margin(1e-12 * 30));
  }
}

TEST_CASE("cylinder vs box: the axis-parallel closed form agrees with the triangles", "[geometry][box]") {
  // The same cylinder tilted by 1e-300 along one cross axis takes the general path (its ends
  // differ there) and is the same solid to the last bit of every distance.
  const Box box{{-1, -2, -3}, {4, 5, 6}};
  const mtcs::mesh::TriangleBvh bvh(mtcs::mesh::box_mesh(box));
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coord(-12, 12), radius(0.05, 3);
  int touching = 0, near = 0;
  for (int i = 0; i < 3000; ++i) {
    const int a = i % 3, u = (a + 1) % 3;
    // Drawn in sequence (a constructor's arguments are evaluated in an unspecified order): the
    // same cases for every compiler. Cases 1000 and 1625 are discs that overlap a face by a
    // sliver, whose rim minimum a sample once met on the crest between two minima.
    const double x = coord(rng), y = coord(rng), z = coord(rng);
    Vec3 p0(x, y, z), p1 = p0;
    p1[a] = coord(rng);
    const Cylinder c{p0, p1, radius(rng)};
    Cylinder tilted = c;
    tilted.p1[u] = std::nextafter(c.p1[u], 1e300);
    const auto ours = distance(c, box);
    const auto general = distance(tilted, box);
    INFO("case " << i);
    CHECK(!ours.bounded);
    CHECK(ours.distance == Approx(general.distance).margin(1e-12 * 30));
    const auto mesh = mtcs::mesh::cylinder_clearance(bvh, c, std::numeric_limits<double>::infinity());
    CHECK(ours.distance == Approx(mesh.distance).margin(1e-12 * 30));
    // The witnesses: on the cylinder and on the box, as far apart as the distance.
    CHECK((ours.on_cylinder - ours.on_triangle).norm() == Approx(ours.distance).margin(1e-12 * 30));
    CHECK(box.contains(ours.on_triangle));
    const Vec3 axis = (c.p1 - c.p0).normalized(), w = ours.on_cylinder - c.p0;
    const double along = w.dot(axis), across = (w - along * axis).norm();
    CHECK(along >= -1e-12);
    CHECK(along <= (c.p1 - c.p0).norm() + 1e-12);
    CHECK(across <= c.radius + 1e-12);
    touching += ours.distance == 0;
    near += ours.distance > 0 && ours.distance < 1;
    // The bound: bounded exactly when the distance reaches it.
    const auto capped = distance(c, box, {.upper_bound = 1.0});
    CHECK(capped.bounded == (ours.distance >= 1.0));
    if (!capped.bounded) CHECK(capped.distance == ours.distance);
  }
  CHECK(touching > 100);
  CHECK(near > 100);
}
