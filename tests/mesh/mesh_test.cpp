// Meshes: validation, STL round trip, and the BVH queries against brute force over all
// triangles and against closed forms.

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <unistd.h>
#include <random>

#include "mtcs/mesh/bvh.h"
#include "mtcs/mesh/mesh_check.h"
#include "mtcs/mesh/mesh_io.h"
#include "support/scratch_file.h"
#include "support/paths.h"
#include "support/random_draws.h"

using namespace mtcs;
using geometry::Vec3;

TEST_CASE("meshes: a box is closed and outward, holes and flipped faces are reported", "[mesh]") {
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
  const auto path = (mtcs_test::scratch_dir("meshes") / "box.stl").string();
  mesh::write_stl(path, box);
  const auto back = mesh::read_mesh(path);
  CHECK(back.triangles.size() == 12);
  CHECK(back.vertices.size() == 8);  // the STL reader merges the corners again
  CHECK(mesh::closed_mesh_problem(back).empty());
  CHECK(back.signed_volume() == Approx(48));
}

TEST_CASE("meshes: BVH segment distance equals brute force, containment", "[mesh]") {
  const auto gear = mesh::read_mesh(MTCS_SOURCE_DIR + "/molds/meshes/mcad_herringbone_gear.off");
  REQUIRE(mesh::closed_mesh_problem(gear).empty());
  const mesh::TriangleBvh bvh(gear);
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(-50, 50);
  for (int i = 0; i < 40; ++i) {
    const Vec3 half_z(1, 1, 0.5);
    const Vec3 a = mtcs_test::draw_vec3(u, rng).cwiseProduct(half_z), b = mtcs_test::draw_vec3(u, rng).cwiseProduct(half_z);
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

TEST_CASE("meshes: validation names self-intersecting triangles, holes and flipped faces", "[mesh]") {
  CHECK(mesh::check_mesh(mesh::box_mesh({{0, 0, 0}, {1, 1, 1}})).ok());
  // Two overlapping boxes in one mesh: closed and oriented, but self-intersecting.
  auto two = mesh::box_mesh({{0, 0, 0}, {2, 2, 2}});
  const auto second = mesh::box_mesh({{1, 1, 1}, {3, 3, 3}});
  for (const Vec3& v : second.vertices) two.vertices.push_back(v);
  for (auto t : second.triangles) two.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
  const auto c = mesh::check_mesh(two);
  CHECK(c.closed_problem.empty());
  REQUIRE_FALSE(c.self_intersections.empty());
  for (const auto& p : c.self_intersections) {  // one from each box
    CHECK(p[0] < 12);
    CHECK(p[1] >= 12);
  }
  const std::string m = c.message();
  CHECK(m.find("intersect each other") != std::string::npos);
  CHECK(m.find(std::to_string(c.self_intersections[0][0]) + "-" + std::to_string(c.self_intersections[0][1])) != std::string::npos);
  // A hole and a flipped face: named by the closedness check.
  auto holed = mesh::box_mesh({{0, 0, 0}, {1, 1, 1}});
  holed.triangles.pop_back();
  CHECK(mesh::check_mesh(holed).message().find("not closed") != std::string::npos);
  auto flipped = mesh::box_mesh({{0, 0, 0}, {1, 1, 1}});
  std::swap(flipped.triangles[3][1], flipped.triangles[3][2]);
  CHECK_FALSE(mesh::check_mesh(flipped).ok());
  // The shipped meshes pass.
  CHECK(mesh::check_mesh(mesh::read_mesh(MTCS_TEST_DATA + "/meshes/homer.off")).ok());
}

TEST_CASE("meshes: OBJ and PLY (colours, quality) read back through CGAL's readers", "[mesh]") {
  const auto gear = mesh::read_mesh(MTCS_TEST_DATA + "/meshes/mcad_herringbone_gear.off");
  const auto dir = mtcs_test::scratch_dir("writers");
  mesh::FaceAttributes faces;
  for (std::size_t t = 0; t < gear.triangles.size(); ++t) {
    faces.colors.push_back({static_cast<unsigned char>(t % 256), 200, 30});
    faces.quality.push_back(double(t) / 7);
  }
  {
    std::ofstream obj(dir / "gear.obj"), ply(dir / "gear.ply");
    mesh::write_obj(obj, gear);
    mesh::write_ply(ply, gear, faces);
  }
  for (const char* name : {"gear.obj", "gear.ply"}) {
    INFO(name);
    const auto back = mesh::read_mesh((dir / name).string());
    REQUIRE(back.triangles.size() == gear.triangles.size());
    CHECK(back.vertices == gear.vertices);  // 17 digits: bit for bit
    CHECK(back.triangles == gear.triangles);
  }
  std::ifstream ply(dir / "gear.ply");
  std::string header((std::istreambuf_iterator<char>(ply)), {});
  CHECK(header.find("property uchar red") != std::string::npos);
  CHECK(header.find("property float quality") != std::string::npos);
  std::filesystem::remove_all(dir);
}
