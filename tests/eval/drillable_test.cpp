// The `drillable` constraint and its accessibility maps against independent references: the
// exact CheckBox map that `mtcs access-map` computes (voxel::part_access_map) at the same pivot
// and tool, closed-form cells of a sphere grid, bores known blocked or free from the gear's
// bounds, and the same verdicts for any thread count.

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <random>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>
#include <unistd.h>

#include "../support/scratch_file.h"
#include "mtcs/eval/drill_access.h"
#include "mtcs/eval/pipeline.h"
#include "mtcs/io/input_error.h"
#include "mtcs/mesh/bvh.h"
#include "mtcs/voxel/part_map.h"
#include "support/paths.h"

using namespace mtcs;
using geometry::Vec3;
namespace fs = std::filesystem;

namespace {

fs::path write(const std::string& name, const std::string& text) {
  return mtcs_test::write_scratch("drillable_test", name, text);
}

// The gear of molds/gear.yaml (74 x 74 x 22 mm, centred at (80, 80, 55)), drilled at angles.
std::string gear_spec(const std::string& access_map = "{grid: 48, cells: [24, 24], entry_step: 1}") {
  return "block: {box: {min: [0, 0, 0], max: [160, 160, 90]}}\n"
         "cavity: {mesh: " + std::string(MTCS_TEST_DATA) + "/meshes/mcad_herringbone_gear.off, translate: [80, 80, 55]}\n"
         "drilling: {diameters: [8], axis_parallel: false, max_angle_deg: 30, access_map: " + access_map + "}\n"
         "circuits: {inlet_faces: [-y], outlet_faces: [-y]}\n"
         // The wall distances, as before temperatures became the default: no void model to build.
         "objectives: {use: [uniformity, worst_covered, cost]}\n";
}

bool any_free(const voxel::AccessMap& map, const std::vector<std::array<int, 2>>& cells) {
  for (const auto& c : cells)
    if (!map.collides(c[0], c[1])) return true;
  return false;
}

}  // namespace

TEST_CASE("drillable: cells of a direction in closed form", "[eval][drillable]") {
  const voxel::SphereGrid s{32, 32};
  // A cell's centre lies in that cell only.
  for (const auto& [i, j] : std::vector<std::array<int, 2>>{{0, 0}, {5, 31}, {16, 8}, {31, 17}})
    CHECK(voxel::cells_of(s, s.direction(i, j)) == std::vector<std::array<int, 2>>{{i, j}});
  // +y: phi = 90 deg, gamma = 90 deg, on the border of rows 15 | 16 and columns 7 | 8.
  CHECK(voxel::cells_of(s, Vec3::UnitY()) == std::vector<std::array<int, 2>>{{16, 8}, {15, 7}, {15, 8}, {16, 7}});
  // +x: gamma = 0 wraps to the last column.
  CHECK(voxel::cells_of(s, Vec3::UnitX()) == std::vector<std::array<int, 2>>{{16, 0}, {15, 0}, {15, 31}, {16, 31}});
  // The pole +z lies in every cell of row 0.
  CHECK(voxel::cells_of(s, Vec3::UnitZ()).size() == 32);
}

TEST_CASE("drillable: every verdict's map equals the exact CheckBox map at the same pivot and tool", "[eval][drillable]") {
  const mold::Scene scene(mold::load_mold_spec(write("gear.yaml", gear_spec()).string()));
  const eval::DrillAccess access(scene);
  const voxel::SphereGrid sphere{24, 24};
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  int free = 0, blocked = 0;
  for (int n = 0; n < 24; ++n) {
    // An entry on -y or +x aimed into the block within 30 deg of the face's normal.
    const bool minus_y = n % 2 == 0;
    const Vec3 entry = minus_y ? Vec3(20 + 120 * u(rng), 0, 30 + 50 * u(rng)) : Vec3(160, 20 + 120 * u(rng), 30 + 50 * u(rng));
    const Vec3 inward = minus_y ? Vec3(0, 1, 0) : Vec3(-1, 0, 0);
    const Vec3 side = minus_y ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
    const double a = (u(rng) - 0.5) * 1.0, b = (u(rng) - 0.5) * 0.6;
    const Vec3 dir = (inward + std::tan(a) * side + std::tan(b) * Vec3::UnitZ()).normalized();
    const double length = 40 + 110 * u(rng);
    const eval::DrillVerdict v = access.check(entry, dir, 8, length);
    REQUIRE(v.map);
    CHECK(v.tool_radius == 12);  // 4 + clearance 1.0 D
    CHECK(v.tool_length >= length);
    CHECK(v.tool_length < length + 1);
    // The map `mtcs access-map` draws (default grid conventions, exact CheckBox).
    const voxel::PartMap ref = voxel::part_access_map(scene.spec().cavity->mesh->mesh, 48, v.pivot,
                                                      voxel::bore_tool(v.tool_radius, v.tool_length), sphere,
                                                      {.method = voxel::AmMethod::checkbox, .threads = 1});
    REQUIRE(!ref.pivot_inside);
    CHECK(v.map->cells == ref.map.cells);
    CHECK(v.free == any_free(ref.map, voxel::cells_of(sphere, dir)));
    (v.free ? free : blocked) += 1;
  }
  // The sample must exercise both verdicts, or it proves little.
  CHECK(free > 0);
  CHECK(blocked > 0);
}

TEST_CASE("drillable: bores known blocked and free", "[eval][drillable]") {
  const mold::Scene scene(mold::load_mold_spec(write("gear.yaml", gear_spec()).string()));
  const eval::Pipeline pipeline(scene);
  REQUIRE(pipeline.drill_access());
  const geometry::Box gear = scene.spec().cavity->mesh->mesh.bounds();
  // Straight along y at x = 10: the tool (r 12) stays 21 mm off the gear's bounding box.
  const mold::Genome beside{{{{{10, 0, 55}, {10, 140, 55}}, 8}}};
  REQUIRE(gear.min.x() - (10 + 12) > 20);
  const auto e1 = pipeline.evaluate(beside);
  for (const auto& v : e1.violations) CHECK(v.kind != eval::ViolationKind::Drillable);
  // Straight through the gear's middle plane at x = 60: the exact cylinder-mesh distance says
  // the hole itself cuts the part, so no map may call it free.
  const mold::Genome through{{{{{60, 0, 55}, {60, 140, 55}}, 8}}};
  const auto clearance = mesh::cylinder_clearance(*scene.cavity_bvh(), {{60, 0, 55}, {60, 140, 55}, 4});
  REQUIRE(clearance.distance == 0);
  const auto e2 = pipeline.evaluate(through);
  bool flagged = false;
  for (const auto& v : e2.violations) flagged = flagged || (v.kind == eval::ViolationKind::Drillable && v.elements.front() == "c0.b0");
  CHECK(flagged);
}

TEST_CASE("drillable: the same verdicts and maps for any thread count", "[eval][drillable]") {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<mold::Genome> layouts;
  for (int n = 0; n < 32; ++n) {
    const Vec3 p(20 + 120 * u(rng), 30 + 100 * u(rng), 35 + 40 * u(rng));
    const Vec3 q(20 + 120 * u(rng), p.y() + 20 * (u(rng) - 0.5), p.z() + 20 * (u(rng) - 0.5));
    layouts.push_back({{{{{p.x(), 0, p.z()}, p, q, {q.x(), 0, q.z()}}, 8}}});
  }
  auto run = [&](int threads) {
    const mold::Scene scene(mold::load_mold_spec(write("gear.yaml", gear_spec()).string()));
    const eval::Pipeline pipeline(scene);
    std::vector<std::string> out(layouts.size());
    tbb::task_arena arena(threads);
    arena.execute([&] {
      tbb::parallel_for(std::size_t(0), layouts.size(), [&](std::size_t k) {
        for (const auto& v : pipeline.evaluate(layouts[k]).violations)
          if (v.kind == eval::ViolationKind::Drillable) out[k] += v.elements.front() + ' ' + std::to_string(v.distance) + ';';
      });
    });
    return std::make_pair(out, pipeline.drill_access()->cache().size());
  };
  const auto one = run(1), two = run(2);
  CHECK(one == two);
  long flagged = 0;
  for (const auto& s : one.first) flagged += !s.empty();
  CHECK(flagged > 0);
  CHECK(flagged < long(layouts.size()));
}

TEST_CASE("drillable: bad access_map fields name the field", "[eval][drillable]") {
  const std::string no_mesh = "block: {box: {min: [0, 0, 0], max: [100, 100, 100]}}\n"
                              "cavity: {box: {min: [40, 40, 40], max: [60, 60, 60]}}\n"
                              "drilling: {access_map: {grid: 32}}\n";
  CHECK_THROWS_WITH(mold::load_mold_spec(write("no_mesh.yaml", no_mesh).string()),
                    Catch::Contains("drilling.access_map") && Catch::Contains("cavity mesh"));
  CHECK_THROWS_WITH(mold::load_mold_spec(write("cells.yaml", gear_spec("{cells: [24]}")).string()),
                    Catch::Contains("drilling.access_map.cells"));
  CHECK_THROWS_WITH(mold::load_mold_spec(write("step.yaml", gear_spec("{entry_step: 0}")).string()),
                    Catch::Contains("drilling.access_map.entry_step"));
}
