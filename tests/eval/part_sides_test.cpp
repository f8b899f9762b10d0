// The part's two sides (cavity.parting, eval::part_sides), each side's spread, and the samples
// of a thin wall's two faces that they need: checked against the bundled cup's and plate's
// geometry, which says by its coordinates which half of the mold forms each face.
#include <catch2/catch.hpp>

#include <cmath>

#include "mtcs/eval/cavity_temperature.h"
#include "mtcs/eval/part_sides.h"
#include "mtcs/eval/pipeline.h"
#include "mtcs/eval/thermal_model.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/run/session.h"
#include "support/bundled_variant.h"
#include "support/paths.h"

using namespace mtcs;
using geometry::Vec3;

namespace {

// The cup of molds/cup.yaml: x 50..170, y 50..130, z 40..80, 2.5 mm walls, open at +z. Its core
// half (the steel inside the cup and above its rim) is the one toward +z.
bool cup_core_steel(const Vec3& q) {
  const bool inside = q.x() > 52.5 && q.x() < 167.5 && q.y() > 52.5 && q.y() < 127.5 && q.z() > 42.5;
  return inside || q.z() > 80;
}

}  // namespace

TEST_CASE("part sides: each of the cup's samples goes to the half whose steel is behind it", "[eval][thermal]") {
  const mold::Scene scene(mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/cup.yaml"));
  const thermal::Samples samples = eval::thermal_samples(scene);
  const std::vector<eval::PartSide> sides = eval::part_sides(scene, samples);
  REQUIRE(sides.size() == samples.size());
  double core = 0, cavity = 0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Vec3 q = samples.points[i] + 1e-3 * samples.normals[i];
    INFO("sample at " << samples.points[i].transpose() << ", normal " << samples.normals[i].transpose());
    CHECK((sides[i] == eval::PartSide::Core) == cup_core_steel(q));
    (sides[i] == eval::PartSide::Core ? core : cavity) += samples.weights[i];
  }
  // The faces' areas: core = inner floor 115 x 75 + inner walls 2 (115 + 75) 37.5 + rim
  // (9 600 - 8 625); cavity = floor 120 x 80 + outer walls 2 (120 + 80) 40. Each piece of a
  // cube goes to its own face's sample, at the thin walls' edges (four faces a cube) too.
  CHECK(core == Approx(8625 + 14250 + 975).epsilon(1e-9));
  CHECK(cavity == Approx(9600 + 16000).epsilon(1e-9));
}

TEST_CASE("part sides: a thin wall's two faces get samples of their own, each with its face's area", "[eval][thermal]") {
  // Cubes of 4 mm take both faces of the cup's 2.5 mm floor: one sample for both put 64 % of
  // the floor's underside at the inner floor's temperature (before the split).
  const run::Session session(MTCS_SOURCE_DIR + "/molds/cup.yaml", run::RunOverrides{});
  const thermal::Samples samples = eval::thermal_samples(session.scene());
  double below = 0, above = 0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    if (samples.normals[i].z() < -0.9) below += samples.weights[i];
    if (samples.normals[i].z() > 0.9) above += samples.weights[i];
  }
  // By the samples' normals: a sample at an edge stands for both faces of its side there (the
  // underside and the outer wall are not turned against each other), with one face's normal.
  CHECK(below == Approx(9600).epsilon(0.04));        // the floor's underside
  CHECK(above == Approx(8625 + 975).epsilon(0.04));  // the inner floor and the rim
}

TEST_CASE("part sides: the plate parted at its top face: the top is the core's, the rest the cavity's", "[eval][thermal]") {
  // Every face (the plate's top takes no heat: not among the heated samples).
  const std::string spec = mtcs_test::bundled_variant(
      "plate", "  tier: t2d\n", "  tier: t2d\n  objective_surface: all\n");
  const mold::Scene scene(mold::load_mold_spec(spec));
  const thermal::Samples samples = eval::thermal_samples(scene);
  const auto sides = eval::part_sides(scene, samples);
  // Temperatures made up to test the summary: 100 + x / 10 on the top, 50 elsewhere.
  std::vector<double> t(samples.size());
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const bool top = samples.normals[i].z() > 0.9;
    CHECK((sides[i] == eval::PartSide::Core) == top);
    t[i] = top ? 100 + samples.points[i].x() / 10 : 50;
  }
  const eval::SideSummaries s = eval::side_summaries(t, samples, sides);
  CHECK(s.core.area == Approx(200 * 150));
  CHECK(s.cavity.area == Approx(200 * 150 + 2 * (200 + 150) * 3));
  // The top's cells: n = 19 columns (at most 11 mm wide) over x 50..250 mm, equal areas, so T
  // takes n equally spaced values 200 / n / 10 K apart: std = step sqrt((n^2 - 1) / 12).
  const double n = std::ceil(200 / 11.0), step = 200 / n / 10;
  CHECK(s.core.mean == Approx(115));
  CHECK(s.core.std == Approx(step * std::sqrt((n * n - 1) / 12)).epsilon(1e-9));
  CHECK(s.cavity.std == Approx(0).margin(1e-9));
  CHECK(s.larger_std() == s.core.std);
}

TEST_CASE("part sides: mtcs thermal's sides and the temperature_std_side objective agree", "[eval][thermal]") {
  // A fixed part film: the stage and mtcs thermal then solve the same problem (no cycle to follow).
  const std::string spec = mtcs_test::bundled_variant(
      "cup", {{"cavity_condition: coupled", "cavity_condition: coupled\n  part_film: 115\n  part_temperature: 230"},
              {"use: [temperature_std, cycle_time, cost]", "use: [temperature_std_side, temperature_std, cost]"}});
  const run::Session session(spec, run::RunOverrides{});
  const mold::Scene& scene = session.scene();
  const mold::Layout layout = mold::decode(scene, session.read_layout(MTCS_SOURCE_DIR + "/molds/cup.layout.yaml"));
  const eval::CavityTemperature r = eval::cavity_temperature(scene, layout, eval::thermal_query(scene.spec()));
  REQUIRE(r.sides);
  INFO("core std " << r.sides->core.std << " K, cavity std " << r.sides->cavity.std << " K, all " << r.summary.std << " K");
  // The core runs hotter than the cavity (the part's heat is trapped inside the cup): the spread
  // over both mixes that offset in, each side's does not.
  CHECK(r.sides->core.mean > r.sides->cavity.mean + 10);
  CHECK(r.sides->larger_std() < r.summary.std);
  const eval::Evaluation e = eval::Pipeline(scene).evaluate(layout);
  CHECK(e.objectives[0] == Approx(r.sides->larger_std()).epsilon(1e-9));
  CHECK(e.objectives[1] == Approx(r.summary.std).epsilon(1e-9));
}

TEST_CASE("part sides: temperature_std_side refuses a side without samples (the plate's unheated top)", "[eval][thermal]") {
  // The plate's top takes no heat, so the heated samples are all the cavity side's: the larger
  // spread would be temperature_std under another name.
  const std::string spec = mtcs_test::bundled_variant("plate", "use: [temperature_std, cycle_time, cost]",
                                                      "use: [temperature_std_side, cost]");
  const mold::Scene scene(mold::load_mold_spec(spec));
  CHECK_THROWS_WITH(eval::Pipeline(scene), Catch::Contains("the core side has no samples of the heated surface"));
}
