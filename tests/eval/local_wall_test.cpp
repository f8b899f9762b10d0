// The part's local wall thickness in the coupled model (cavity.wall_thickness: local): each
// cavity triangle's film at its own wall, the cycle set by the place that cools last.
#include <catch2/catch.hpp>

#include <algorithm>

#include "mtcs/eval/cavity_temperature.h"
#include "mtcs/eval/cycle_time.h"
#include "mtcs/eval/part_coupling.h"
#include "mtcs/eval/thermal_model.h"
#include "mtcs/mesh/wall_thickness.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/run/session.h"
#include "support/paths.h"

using namespace mtcs;
using geometry::Vec3;

TEST_CASE("local wall: the ribbed box's films follow its walls, the thickest one sets the cycle", "[eval][coupling]") {
  const run::Session session(MTCS_SOURCE_DIR + "/molds/ribbed_box.yaml",
                             run::RunOverrides{});
  const mold::Scene& scene = session.scene();
  const mold::MoldSpec& spec = scene.spec();
  const std::vector<double>& wall = scene.cavity_thickness();
  const mesh::TriangleMesh& part = spec.cavity->mesh->mesh;
  REQUIRE(wall.size() == part.triangles.size());
  // The scene's thickest wall is the spec's now: the boss, thicker than the 2.5 mm shell.
  const double thickest = *std::max_element(wall.begin(), wall.end());
  CHECK(spec.cavity->wall_thickness == thickest);
  CHECK(thickest > 5);
  CHECK(std::count_if(wall.begin(), wall.end(), [](double s) { return std::abs(s - 2.5) < 0.01; }) > 10);

  // Each heated triangle's film is part_coupling's at its own wall, in the nominal cycle.
  const thermal::Setting setting = eval::thermal_setting(scene);
  const eval::CycleTimes times = eval::nominal_cycle(spec);
  REQUIRE(setting.heat_in.size() == wall.size());
  for (std::size_t t = 0; t < wall.size(); t += 7) {
    INFO("triangle " << t << ", wall " << wall[t] << " mm");
    CHECK(setting.heat_in[t].film ==
          Approx(eval::part_coupling(spec.thermal.polymer, wall[t], times.in_mold, times.cycle).film).epsilon(1e-12));
  }
  // A thinner wall gives less heat per area and cycle (it holds less).
  const auto [thin, thick] = std::minmax_element(wall.begin(), wall.end());
  CHECK(setting.heat_in[std::size_t(thin - wall.begin())].film < setting.heat_in[std::size_t(thick - wall.begin())].film);

  // The cycle is the cooling time of the place that cools last, at its wall and temperature.
  const mold::Layout layout = mold::decode(scene, session.read_layout(MTCS_SOURCE_DIR + "/molds/ribbed_box.layout.yaml"));
  const eval::CavityTemperature r = eval::cavity_temperature(scene, layout, eval::thermal_query(spec));
  const thermal::Samples samples = eval::thermal_samples(scene);
  REQUIRE(samples.thickness.size() == samples.size());
  const std::size_t k = eval::slowest_place(r.at_samples, samples.thickness, spec.thermal.polymer, samples.size());
  INFO("slowest place " << samples.points[k].transpose() << ", wall " << samples.thickness[k] << " mm, "
                        << r.at_samples[k] << " C; cycle " << r.cycle_time << " s");
  CHECK(r.condition.local_wall);
  CHECK(r.condition.wall_thickest >= thickest);  // a sample may lie where no centroid does
  CHECK(r.condition.wall_thickest == *std::max_element(samples.thickness.begin(), samples.thickness.end()));
  CHECK(r.condition.wall_thinnest < 2.5);
  CHECK(r.slowest == samples.points[k]);
  CHECK(r.slowest_wall == samples.thickness[k]);
  CHECK(r.cooling_time == Approx(eval::cooling_time(samples.thickness[k], spec.thermal.polymer, r.at_samples[k])).epsilon(1e-12));
  for (std::size_t i = 0; i < samples.size(); ++i)
    REQUIRE(eval::cooling_time(samples.thickness[i], spec.thermal.polymer, r.at_samples[i]) <= r.cooling_time * (1 + 1e-12));
  // Each sample's wall is the inscribed ball's at that sample.
  for (std::size_t i = 0; i < samples.size(); i += 97)
    CHECK(samples.thickness[i] == mesh::inscribed_diameter(*scene.cavity_bvh(), samples.points[i], samples.normals[i], 1e3));
}

TEST_CASE("local wall: the optimiser's cycle from one solve is the fixed point's", "[eval][coupling]") {
  // The optimiser's one-solve cycle (follow_cycle) against mtcs thermal's whole-solve fixed point.
  const run::Session session(MTCS_SOURCE_DIR + "/molds/l_bracket.yaml",
                             run::RunOverrides{});
  const mold::Scene& scene = session.scene();
  const mold::Genome genome = session.read_layout(MTCS_SOURCE_DIR + "/molds/l_bracket.layout.yaml");
  const eval::CavityTemperature fixed_point =
      eval::cavity_temperature(scene, mold::decode(scene, genome), eval::thermal_query(scene.spec()));
  REQUIRE(fixed_point.ejectable);
  const eval::Evaluation e = session.pipeline().evaluate(genome);
  const auto& use = scene.spec().objectives.use;
  const std::size_t cycle = std::size_t(std::find(use.begin(), use.end(), mold::Objective::CycleTime) - use.begin());
  REQUIRE(cycle < use.size());
  INFO("optimiser " << e.objectives[cycle] << " s, fixed point " << fixed_point.cycle_time << " s");
  CHECK(e.objectives[cycle] == Approx(fixed_point.cycle_time).epsilon(0.05));
}
