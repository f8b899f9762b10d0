// Meshes: validation, STL round trip, and the BVH queries against brute force over all
// triangles and against closed forms.

#include <catch2/catch.hpp>
#include <filesystem>
#include <random>

#include "mtcs/mesh/bvh.h"
#include "mtcs/mesh/mesh_io.h"

using namespace mtcs;
using geometry::Vec3;

TEST_CASE("meshes: a box is closed and outward; holes and flipped faces are reported", "[mesh]") {
  auto box = mesh::box_mesh({{0, 0, 0}, {2, 3, 4}});
  CHECK(mesh::closed_mesh_problem(box).empty());
  CHECK(box.signed_volume() == Approx(24));
  CHECK(box.area() == Approx(2 * (6 + 8 + 12)));
  auto holed = box;
  holed.triangles.pop_back();
  CHECK(mesh::closed_mesh_problem(holed).find("not closed") != std::string::npos);
  auto flipped = box;
  std::swap(flipped.triangles[3][1], flipped.triangles[3][2]);
  CHECK_FALSE(mesh::closed_mesh_problem(flipped).empty());
}

TEST_CASE("meshes: binary STL round trip through CGAL's reader", "[mesh]") {
  const auto box = mesh::box_mesh({{-1, -2, -3}, {1, 2, 3}});
  const auto path = (std::filesystem::temp_directory_path() / "mtcs_box.stl").string();
  mesh::write_stl(path, box);
  const auto back = mesh::read_mesh(path);
  CHECK(back.triangles.size() == 12);
  CHECK(back.vertices.size() == 8);  // the STL reader merges the corners again
  CHECK(mesh::closed_mesh_problem(back).empty());
  CHECK(back.signed_volume() == Approx(48));
}

TEST_CASE("meshes: BVH segment distance equals brute force; containment", "[mesh]") {
  const auto gear = mesh::read_mesh(MTCS_SOURCE_DIR "/molds/meshes/mcad_herringbone_gear.off");
  REQUIRE(mesh::closed_mesh_problem(gear).empty());
  const mesh::TriangleBvh bvh(gear);
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(-50, 50);
  for (int i = 0; i < 40; ++i) {
    const Vec3 a(u(rng), u(rng), u(rng) / 2), b(u(rng), u(rng), u(rng) / 2);
    double brute = std::numeric_limits<double>::infinity();
    for (std::size_t t = 0; t < gear.triangles.size(); ++t)
      brute = std::min(brute, geometry::segment_triangle_distance(a, b, gear.corner(t, 0), gear.corner(t, 1), gear.corner(t, 2)));
    CHECK(bvh.segment_distance(a, b, 1e9) == Approx(brute).margin(1e-12));
    // With a cap: exact below it, at least the cap above it.
    const double capped = bvh.segment_distance(a, b, 5);
    if (brute < 5) CHECK(capped == Approx(brute).margin(1e-12));
    else CHECK(capped >= 5);
  }
  // The hub is solid between the bore (radius ~5) and the lightening holes.
  CHECK_FALSE(bvh.contains({0, 0, 0}));      // in the shaft bore
  CHECK_FALSE(bvh.contains({0, 0, 30}));     // above the gear
  CHECK(bvh.contains({35, 0, 0}));           // in the rim
}

TEST_CASE("meshes: cylinder clearance has closed forms on a box", "[mesh]") {
  const mesh::TriangleBvh bvh(mesh::box_mesh({{0, 0, 0}, {10, 10, 10}}));
  auto clearance = [&](const Vec3& p0, const Vec3& p1, double r, double cap) {
    return mesh::cylinder_clearance(bvh, {p0, p1, r}, cap);
  };
  // Parallel to the top face at a gap of 3 (axis 5 above, radius 2).
  CHECK(clearance({-5, 5, 15}, {15, 5, 15}, 2, 100).distance == Approx(3).epsilon(1e-14));
  // End disk facing the top face at a gap of 3: the capsule would say 3 - radius.
  CHECK(clearance({5, 5, 13}, {5, 5, 30}, 2, 100).distance == Approx(3).epsilon(1e-14));
  // Beyond a corner edge along the axis direction: the rim, not the capsule, is nearest.
  // Axis along z above the edge x = 10, z = 10 shifted out by 1 in x: rim point (10 + 1 - 2, ...)
  // lies over the box top, so the gap is the height 1.
  CHECK(clearance({11, 5, 11}, {11, 5, 20}, 2, 100).distance == Approx(1).epsilon(1e-14));
  // Crossing the box: 0. Buried inside: 0 (containment, no surface contact).
  CHECK(clearance({-5, 5, 5}, {15, 5, 5}, 1, 100).distance == 0);
  const auto buried = clearance({3, 5, 5}, {7, 5, 5}, 1, 100);
  CHECK(buried.distance == 0);
  CHECK(buried.buried);
  // Buried and the upper bound below every surface distance: still 0, not bounded.
  CHECK(clearance({3, 5, 5}, {7, 5, 5}, 1, 0.5).distance == 0);
  // Capped.
  const auto far = clearance({-5, 5, 50}, {15, 5, 50}, 1, 10);
  CHECK(far.bounded);
  CHECK(far.distance >= 10);
}

TEST_CASE("meshes: containment when the ray passes through an edge or a vertex", "[mesh]") {
  // Points placed so that the first ray direction exits through a face centre (on the face's
  // diagonal edge, shared by its two triangles) or through a corner vertex.
  const mesh::TriangleBvh bvh(mesh::box_mesh({{0, 0, 0}, {10, 10, 10}}));
  const Vec3 d = Vec3(0.5390, 0.6187, 0.5716).normalized();
  for (const Vec3& exit : {Vec3(10, 5, 5), Vec3(5, 10, 5), Vec3(5, 5, 10), Vec3(10, 10, 10), Vec3(10, 10, 4)}) {
    INFO("exit " << exit.transpose());
    CHECK(bvh.contains(exit - 3 * d));
    CHECK_FALSE(bvh.contains(exit + 3 * d));
  }
}
