// Accessibility maps: every public case reproduced cell for cell by every method; a brute force
// over all solid voxels on small grids; a segment tool against a single box (ray-box slab test);
// a pivot inside the part; empty and full grids; the same map and counters on 1 and 2 threads.

#include <catch2/catch.hpp>
#include <random>

#include "mtcs/voxel/accessibility_map.h"
#include "voxel/check_box.h"
#include "voxel/case_files.h"
#include "support/paths.h"
#include "support/random_draws.h"

using namespace mtcs;
using namespace mtcs::voxel;

namespace {

const AmMethod kMethods[] = {AmMethod::checkbox, AmMethod::ica, AmMethod::aica};

AmOptions with(AmMethod m, int threads = 0) {
  AmOptions o;
  o.method = m;
  o.threads = threads;
  return o;
}

}  // namespace

TEST_CASE("every public case is reproduced cell for cell by every method", "[voxel][am][cases]") {
  long cells = 0;
  for (const auto& path : testing::case_paths()) {
    const AccessCase c = read_access_case(path);
    const Octree& tree = testing::case_octree(c);
    for (AmMethod m : kMethods) {
      INFO(path << " method " << to_string(m));
      const AccessMap map = compute_access_map(tree, c.pivot, c.tool, c.sphere, with(m));
      REQUIRE(map.rows() == c.am);
      CHECK(map.collisions() == c.collisions);
      CHECK(map.stats.undecided == 0);
      cells += long(map.cells.size());
    }
  }
  CHECK(cells == 60 * 3 * 1024);
}

namespace {

// Brute force: a direction collides iff CheckBox says so for some solid voxel box.
std::vector<std::uint8_t> brute_force(const VoxelGrid& g, const Vec3& pivot, const Tool& tool, const SphereGrid& s) {
  std::vector<std::uint8_t> cells(std::size_t(s.rows * s.cols), 0);
  for (int i = 0; i < s.rows; ++i)
    for (int j = 0; j < s.cols; ++j) {
      const CheckBox test(pivot, s.direction(i, j), tool);
      bool hit = false;
      for (int z = 0; z < g.spec.size[2] && !hit; ++z)
        for (int y = 0; y < g.spec.size[1] && !hit; ++y)
          for (int x = 0; x < g.spec.size[0] && !hit; ++x) hit = g.at(x, y, z) && test(g.voxel_box(x, y, z)).collision;
      cells[std::size_t(i * s.cols + j)] = hit;
    }
  return cells;
}

}  // namespace

TEST_CASE("every method equals a brute force over all solid voxels on small grids", "[voxel][am]") {
  // The gear and homer at 16^3 and 12 x 10^3 voxels (a non-cubic grid pads the octree).
  long colliding = 0, free = 0;
  for (const char* name : {"drilling_mcad_herringbone_gear_p00.txt", "drilling_homer_p03.txt"}) {
    const AccessCase c = read_access_case(std::string(MTCS_TEST_DATA) + "/access_maps/" + name);
    const mesh::TriangleMesh part = testing::case_mesh(c);
    for (const GridSpec& g : {GridSpec{{16, 16, 16}, 50.0 / 16, Vec3::Constant(-25)},
                              GridSpec{{12, 10, 10}, 5.0, Vec3(-30, -25, -25)}}) {
      const VoxelGrid grid = voxelize(part, g);
      const Octree tree(grid);
      std::mt19937_64 rng(7);
      std::uniform_real_distribution<double> U(-32, 32);
      int pivots = 0;
      while (pivots < 4) {
        const Vec3 pivot = mtcs_test::draw_vec3(U, rng);
        if (tree.touches_solid(pivot)) continue;
        ++pivots;
        const Tool tool = pivots % 2 ? Tool{{0, 60, 4}} : Tool{{0, 10, 2}, {10, 60, 6}};
        const SphereGrid sphere{12, 16};
        const auto expected = brute_force(grid, pivot, tool, sphere);
        for (auto e : expected) (e ? colliding : free) += 1;
        for (AmMethod m : kMethods) {
          INFO(name << " pivot " << pivot.transpose() << " method " << to_string(m));
          CHECK(compute_access_map(tree, pivot, tool, sphere, with(m)).cells == expected);
        }
      }
    }
  }
  CHECK(colliding > 300);  // both kinds of cells are plentiful
  CHECK(free > 300);
}

TEST_CASE("a segment tool against a single box follows the ray-box slab test", "[voxel][am]") {
  // One solid voxel: the grid's middle voxel of a 3^3 grid of 2 mm voxels, box [-1, 1]^3.
  GridSpec g{{3, 3, 3}, 2.0, Vec3::Constant(-3)};
  const VoxelGrid grid = voxelize(mesh::box_mesh({Vec3::Constant(-1.5), Vec3::Constant(1.5)}), g);
  REQUIRE(grid.count() == 1);
  const Octree tree(grid);
  const Vec3 pivot(0.3, -0.2, -6);
  const SphereGrid sphere{48, 48};
  int compared = 0, hits = 0;
  for (double length : {4.0, 5.5, 20.0}) {
    const Tool tool{{0, length, 0}};
    const AccessMap maps[] = {compute_access_map(tree, pivot, tool, sphere, with(AmMethod::checkbox)),
                              compute_access_map(tree, pivot, tool, sphere, with(AmMethod::ica)),
                              compute_access_map(tree, pivot, tool, sphere, with(AmMethod::aica))};
    for (int i = 0; i < sphere.rows; ++i)
      for (int j = 0; j < sphere.cols; ++j) {
        // Slab test of the segment pivot + t d, 0 <= t <= length, against [-1, 1]^3.
        const Vec3 d = sphere.direction(i, j).normalized();
        double lo = 0, hi = length, margin = 1e300;
        for (int k = 0; k < 3; ++k) {
          if (d[k] == 0) continue;
          double t1 = (-1 - pivot[k]) / d[k], t2 = (1 - pivot[k]) / d[k];
          if (t1 > t2) std::swap(t1, t2);
          lo = std::max(lo, t1);
          hi = std::min(hi, t2);
        }
        margin = std::abs(hi - lo);
        if (margin < 1e-9) continue;  // grazing: not decidable by this double test
        ++compared;
        hits += lo <= hi;
        for (const AccessMap& m : maps) REQUIRE(m.collides(i, j) == (lo <= hi));
      }
  }
  CHECK(compared > 6000);
  CHECK(hits > 20);
}

TEST_CASE("a pivot inside the part is an error, empty and full grids", "[voxel][am]") {
  GridSpec g{{8, 8, 8}, 1.0, Vec3::Zero()};
  const Octree full(voxelize(mesh::box_mesh({Vec3::Constant(-1), Vec3::Constant(9)}), g));
  const Tool tool{{0, 5, 1}};
  const SphereGrid sphere{16, 16};
  CHECK_THROWS_AS(compute_access_map(full, Vec3(4.2, 4.1, 3.3), tool, sphere), std::invalid_argument);
  CHECK_THROWS_AS(compute_access_map(full, Vec3(8, 4, 4), tool, sphere), std::invalid_argument);  // on a voxel face
  CHECK_THROWS_AS(compute_access_map(full, Vec3(9, 4, 4), Tool{{2, 1, 1}}, sphere), std::invalid_argument);
  // Full grid, pivot 1 mm beyond the face x = 8: a direction collides iff the tool meets the
  // grid's box, a single CheckBox.
  const Vec3 pivot(9, 4, 4);
  const Box block{Vec3::Zero(), Vec3::Constant(8)};
  for (AmMethod m : kMethods) {
    const AccessMap map = compute_access_map(full, pivot, tool, sphere, with(m));
    for (int i = 0; i < sphere.rows; ++i)
      for (int j = 0; j < sphere.cols; ++j)
        REQUIRE(map.collides(i, j) == CheckBox(pivot, sphere.direction(i, j), tool)(block).collision);
    CHECK(map.collisions() > 0);
    CHECK(map.collisions() < 256);
  }
  // Empty grid: every direction is free.
  const Octree empty(voxelize(mesh::box_mesh({Vec3::Constant(20), Vec3::Constant(21)}), g));
  for (AmMethod m : kMethods) CHECK(compute_access_map(empty, pivot, tool, sphere, with(m)).collisions() == 0);
}

TEST_CASE("degenerate tools: radius 0 and length 0 agree across methods", "[voxel][am]") {
  const AccessCase c = read_access_case(std::string(MTCS_TEST_DATA) + "/access_maps/drilling_fandisk_large_p02.txt");
  const Octree& tree = testing::case_octree(c);
  for (const Tool& tool : {Tool{{0, 60, 0}}, Tool{{0, 0, 5}}, Tool{{10, 10, 0}}, Tool{{0, 30, 0}, {30, 30, 8}}}) {
    const AccessMap reference = compute_access_map(tree, c.pivot, tool, SphereGrid{24, 24}, with(AmMethod::checkbox));
    for (AmMethod m : {AmMethod::ica, AmMethod::aica})
      CHECK(compute_access_map(tree, c.pivot, tool, SphereGrid{24, 24}, with(m)).cells == reference.cells);
  }
  // The bore of the case with radius 0 collides in no more directions than with its radius.
  const AccessMap thin = compute_access_map(tree, c.pivot, Tool{{0, c.tool[0].b, 0}}, c.sphere);
  CHECK(thin.collisions() <= c.collisions);
  CHECK(thin.collisions() > 0);
}

TEST_CASE("the same map and counters on 1 and 2 threads", "[voxel][am]") {
  const AccessCase c = read_access_case(std::string(MTCS_TEST_DATA) + "/access_maps/public_homer_N128_am32_p04.txt");
  const Octree& tree = testing::case_octree(c);
  for (AmMethod m : kMethods) {
    const AccessMap one = compute_access_map(tree, c.pivot, c.tool, c.sphere, with(m, 1));
    const AccessMap two = compute_access_map(tree, c.pivot, c.tool, c.sphere, with(m, 2));
    CHECK(one.cells == two.cells);
    CHECK(one.stats.node_tests == two.stats.node_tests);
    CHECK(one.stats.checkbox_calls == two.stats.checkbox_calls);
  }
}

TEST_CASE("directions are the sphere grid's, and out-of-reach cylinders change nothing", "[voxel][am]") {
  const AccessCase c = read_access_case(std::string(MTCS_TEST_DATA) + "/access_maps/drilling_homer_p01.txt");
  const Octree& tree = testing::case_octree(c);
  // A holder starting 500 mm out cannot reach a 50 mm part; alone it leaves every cell free.
  Tool with_holder = c.tool;
  with_holder.push_back({500, 600, 100});
  for (AmMethod m : kMethods) {
    CHECK(compute_access_map(tree, c.pivot, with_holder, c.sphere, with(m)).rows() == c.am);
    CHECK(compute_access_map(tree, c.pivot, Tool{{500, 600, 100}}, c.sphere, with(m)).collisions() == 0);
  }
  // A cell's verdict is CheckBox's over the full nodes (which cover the solid voxels exactly)
  // for SphereGrid::direction (row 10, column 3 of a 32 x 32 map).
  const AccessMap map = compute_access_map(tree, c.pivot, c.tool, c.sphere);
  bool any = false;
  for (std::uint32_t i = 0; i < tree.nodes().size(); ++i)
    if (tree.nodes()[i].full) any = any || CheckBox(c.pivot, c.sphere.direction(10, 3), c.tool)(tree.node_box(i)).collision;
  CHECK(map.collides(10, 3) == any);
}

TEST_CASE("memo levels and sub-voxel levels change the work, not the map", "[voxel][am]") {
  for (const char* name : {"public_fandisk_large_N128_am32_p07.txt", "drilling_mcad_herringbone_gear_p06.txt",
                           "public_homer_N128_am32_p02.txt", "drilling_homer_p08.txt"}) {
    const AccessCase c = read_access_case(std::string(MTCS_TEST_DATA) + "/access_maps/" + name);
    const Octree& tree = testing::case_octree(c);
    for (AmMethod m : {AmMethod::ica, AmMethod::aica})
      for (int memo : {0, 3, 6})
        for (int sub : {0, 2}) {
          AmOptions o = with(m);
          o.memo_levels = memo;
          o.subvoxel_levels = sub;
          INFO(name << ' ' << to_string(m) << " memo " << memo << " sub " << sub);
          const AccessMap map = compute_access_map(tree, c.pivot, c.tool, c.sphere, o);
          CHECK(map.rows() == c.am);
          CHECK(map.stats.memo_nodes == (memo == 0 ? 0u : tree.level_end(memo - 1)));
        }
  }
}
