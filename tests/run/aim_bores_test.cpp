// AM-guided drilling directions: a bore through the gear is turned about its entry to a
// direction the map at that entry calls free, within the entry angle limit, while the other
// bores of its circuit keep their directions; and sampled layouts of a mold with
// drilling.access_map have fewer blocked bores with the guidance than without.

#include <catch2/catch.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "mtcs/eval/drill_access.h"
#include "mtcs/eval/pipeline.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/run/mold_problem.h"
#include "run/aim_bores.h"
#include "support/scratch_file.h"
#include "support/paths.h"

using namespace mtcs;
using geometry::Vec3;

namespace {

std::string gear_spec_path() {
  const auto dir = mtcs_test::scratch_dir("aim");
  const auto p = dir / "gear.yaml";
  std::ofstream(p) << "block: {box: {min: [0, 0, 0], max: [160, 160, 90]}}\n"
                      "cavity: {mesh: " + MTCS_TEST_DATA + "/meshes/mcad_herringbone_gear.off, translate: [80, 80, 55]}\n"
                      "drilling: {diameters: [8], axis_parallel: false, max_angle_deg: 30, allowed_faces: [-y, +y, -x, +x],\n"
                      "           access_map: {grid: 48, cells: [24, 24]}}\n"
                      "circuits: {inlet_faces: [-y], outlet_faces: [-y]}\n"
                      // The wall distances, as before temperatures became the default: no void model.
                      "objectives: {use: [uniformity, worst_covered, cost]}\n";
  return p.string();
}

long blocked_bores(const eval::Pipeline& pipeline, const run::MoldProblem& problem, int samples) {
  long blocked = 0;
  for (int s = 0; s < samples; ++s) {
    opt::Rng rng(1000 + std::uint64_t(s));
    for (const auto& v : pipeline.evaluate(problem.genome(problem.sample(rng))).violations)
      blocked += v.kind == eval::ViolationKind::Drillable;
  }
  return blocked;
}

}  // namespace

TEST_CASE("aim_bores turns a blocked bore to a free direction and keeps the others' directions", "[run][drillable]") {
  const mold::Scene scene(mold::load_mold_spec(gear_spec_path()));
  const eval::Pipeline pipeline(scene);
  const eval::DrillAccess& access = *pipeline.drill_access();
  // In at x = 60 through the gear's middle plane, across at y = 130 behind it, out at x = 140.
  mold::Circuit c{{{60, 0, 55}, {60, 130, 55}, {140, 130, 55}, {140, 0, 55}}, 8};
  const mold::Layout before = mold::decode(scene, mold::Genome{{c}});
  REQUIRE_FALSE(access.check(before.bores[0]).free);
  REQUIRE(access.check(before.bores[2]).free);
  opt::Rng rng(3);
  CHECK(run::aim_bores(access, scene, c, rng) >= 1);
  const mold::Layout after = mold::decode(scene, mold::Genome{{c}});
  REQUIRE(after.bores.size() == 3);
  const mold::Bore& b = after.bores[0];
  CHECK(b.hole.p0 == Vec3(60, 0, 55));  // the inlet, its entry, did not move
  CHECK(access.check(b).free);
  CHECK(b.entry_angle_deg <= 30 + 1e-9);
  // The rest of the circuit moved with the turned bore's far end: same directions as before.
  for (std::size_t k = 1; k < 3; ++k) {
    const Vec3 u = (before.bores[k].flow_end - before.bores[k].flow_start).normalized();
    const Vec3 v = (after.bores[k].flow_end - after.bores[k].flow_start).normalized();
    CHECK((u - v).norm() < 1e-12);
  }
}

TEST_CASE("AM-guided sampling leaves fewer blocked bores than unguided sampling", "[run][drillable]") {
  const mold::Scene scene(mold::load_mold_spec(gear_spec_path()));
  const eval::Pipeline pipeline(scene);
  run::MutationRates guided, unguided;
  unguided.access_guided = false;
  const long with = blocked_bores(pipeline, run::MoldProblem(pipeline, {}, guided), 60);
  const long without = blocked_bores(pipeline, run::MoldProblem(pipeline, {}, unguided), 60);
  CHECK(without > 0);
  CHECK(with < without);
}
