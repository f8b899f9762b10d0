// Voxelisation and octree counts against every case file (solid_voxels and octree_nodes were
// computed by an independent implementation), and exact behaviour at vertices, edges and faces
// on a box whose surface passes through voxel centres.

#include <catch2/catch.hpp>

#include "mtcs/mesh/triangle_mesh.h"
#include "mtcs/voxel/part_map.h"
#include "voxel/case_files.h"

using namespace mtcs;
using namespace mtcs::voxel;

TEST_CASE("voxel counts and octree nodes equal every case file", "[voxel][cases]") {
  const auto paths = testing::case_paths();
  REQUIRE(paths.size() == 60);
  for (const auto& path : paths) {
    const AccessCase c = read_access_case(path);
    const Octree& tree = testing::case_octree(c);
    INFO(path);
    CHECK(long(tree.solid_voxels()) == c.solid_voxels);
    CHECK(long(tree.nodes().size()) == c.octree_nodes);
  }
}

namespace {

// Brute force: a centre is solid iff strictly inside the box (the box is convex).
std::size_t strictly_inside_count(const Box& box, const GridSpec& g) {
  std::size_t n = 0;
  for (int k = 0; k < g.size[2]; ++k)
    for (int j = 0; j < g.size[1]; ++j)
      for (int i = 0; i < g.size[0]; ++i) {
        const Vec3 p(g.centre(0, i), g.centre(1, j), g.centre(2, k));
        n += (p.array() > box.min.array()).all() && (p.array() < box.max.array()).all();
      }
  return n;
}

}  // namespace

TEST_CASE("centres on faces, edges and vertices of the surface are not solid", "[voxel]") {
  GridSpec g;
  g.size = {8, 8, 8};
  g.voxel_size = 1;
  g.origin = Vec3::Zero();  // centres at 0.5, 1.5, ..., 7.5
  // Faces through centre planes (1.5 and 5.5): rays graze vertices and run along edges.
  const Box on_centres{Vec3(1.5, 1.5, 1.5), Vec3(5.5, 5.5, 5.5)};
  const VoxelGrid a = voxelize(mesh::box_mesh(on_centres), g);
  CHECK(a.count() == strictly_inside_count(on_centres, g));
  CHECK(a.count() == 27);
  // Faces between centre planes.
  const Box between{Vec3(1.2, 1.0, 2.0), Vec3(5.0, 6.0, 7.0)};
  CHECK(voxelize(mesh::box_mesh(between), g).count() == strictly_inside_count(between, g));
  // Reversed orientation: winding -1 inside, still solid.
  mesh::TriangleMesh flipped = mesh::box_mesh(on_centres);
  for (auto& t : flipped.triangles) std::swap(t[1], t[2]);
  CHECK(voxelize(flipped, g).count() == 27);
  // The octree of a full 4x4x4 block in an 8^3 grid: root, one full child.
  GridSpec g4 = g;
  const Box block{Vec3(0, 0, 0), Vec3(4, 4, 4)};
  const Octree tree(voxelize(mesh::box_mesh(block), g4));
  // Centres 0.5..3.5 are strictly inside [0, 4] only for 0.5..3.5: all 64, a full octant.
  REQUIRE(tree.solid_voxels() == 64);
  CHECK(tree.nodes().size() == 2);
  CHECK(tree.nodes()[1].full == 1);
  CHECK(tree.nodes()[1].level == 1);
}

TEST_CASE("a tetrahedron with vertices and edges on voxel centres", "[voxel]") {
  GridSpec g;
  g.size = {6, 6, 6};
  g.voxel_size = 1;
  g.origin = Vec3::Constant(-0.5);  // centres at integers 0..5
  mesh::TriangleMesh tet;
  tet.vertices = {Vec3(0, 0, 0), Vec3(5, 0, 0), Vec3(0, 5, 0), Vec3(0, 0, 5)};
  tet.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  // Strictly inside: x, y, z > 0 and x + y + z < 5: integer points (1..) with sum <= 4.
  std::size_t expected = 0;
  for (int x = 1; x < 5; ++x)
    for (int y = 1; y < 5; ++y)
      for (int z = 1; z < 5; ++z) expected += x + y + z < 5;
  CHECK(voxelize(tet, g).count() == expected);
}

TEST_CASE("empty and full grids give empty and one-node octrees", "[voxel]") {
  GridSpec g;
  g.size = {4, 4, 4};
  g.voxel_size = 1;
  g.origin = Vec3::Zero();
  const Octree empty(voxelize(mesh::box_mesh({Vec3(10, 10, 10), Vec3(11, 11, 11)}), g));
  CHECK(empty.nodes().empty());
  const Octree full(voxelize(mesh::box_mesh({Vec3(-1, -1, -1), Vec3(5, 5, 5)}), g));
  REQUIRE(full.nodes().size() == 1);
  CHECK(full.nodes()[0].full == 1);
  CHECK(full.solid_voxels() == 64);
}

// The user form's grid (mtcs access-map MESH): N^3 voxels of (largest extent) / (N - 2), the
// bounding box centred, so a cube fills exactly (N - 2)^3 voxels.
TEST_CASE("part_grid pads the part by one voxel, part_access_map refuses a pivot inside", "[voxel]") {
  const Box cube{Vec3(-2, -1, 3), Vec3(2, 3, 7)};  // 4 mm on every axis
  const mesh::TriangleMesh part = mesh::box_mesh(cube);
  const GridSpec g = part_grid(part, 10);
  CHECK(g.voxel_size == 0.5);
  CHECK(g.origin.isApprox(Vec3(-2.5, -1.5, 2.5)));
  CHECK(voxelize(part, g).count() == 8u * 8u * 8u);
  // A flat box: the grid is a cube about the box's centre (even extents keep faces between
  // centre planes; an odd one would put centres on the faces, which are not inside).
  const Box slab{Vec3(0, 0, 0), Vec3(8, 4, 2)};
  const GridSpec s = part_grid(mesh::box_mesh(slab), 10);
  CHECK(s.voxel_size == 1.0);
  CHECK(s.origin.isApprox(Vec3(-1, -3, -4)));
  CHECK(voxelize(mesh::box_mesh(slab), s).count() == 8u * 4u * 2u);
  CHECK_THROWS_AS(part_grid(part, 2), std::invalid_argument);

  const Tool bore = bore_tool(0.5, 20);
  CHECK(tool_problem(bore).empty());
  CHECK_FALSE(tool_problem(Tool{}).empty());
  CHECK_FALSE(tool_problem(Tool{{5, 1, 1}}).empty());
  CHECK_FALSE(tool_problem(Tool{{0, 1, -1}}).empty());
  // Inside the part, on its surface (the closed box of a solid voxel), and just outside.
  CHECK(part_access_map(part, 10, Vec3(0, 1, 5), bore, SphereGrid{4, 4}).pivot_inside);
  CHECK(part_access_map(part, 10, Vec3(2, 1, 5), bore, SphereGrid{4, 4}).pivot_inside);
  const PartMap out = part_access_map(part, 10, Vec3(0, 1, 7.75), bore, SphereGrid{4, 4});
  REQUIRE_FALSE(out.pivot_inside);
  CHECK(out.solid_voxels == 512u);
  // Rows 0-1 point up (free), rows 2-3 down into the top face 0.75 mm below: every cell collides.
  CHECK(out.map.rows() == std::vector<std::string>{"0000", "0000", "1111", "1111"});
}
