// How MoldProblem ranks a layout for SMS-EMOA under each penalty variant: constrained domination
// keeps the score; the static penalties add weight x CV (or CV^2), in scaled units, to every
// objective; death makes an infeasible layout infinitely bad. Checked on a layout through an
// ejector pin of the demo plate against its own evaluation.

#include <catch2/catch.hpp>
#include <cmath>

#include "mtcs/run/mold_problem.h"
#include "mtcs/eval/pipeline.h"
#include "mtcs/mold/scene.h"

using namespace mtcs;

namespace {

// One U circuit in the z = 50 plane whose first leg runs along y through ejector0 (x = 60, y = 35).
mold::Genome through_ejector() {
  mold::Circuit c;
  c.diameter = 8;
  c.waypoints = {{60, 0, 50}, {60, 100, 50}, {150, 100, 50}, {150, 0, 50}};
  return {{c}};
}

opt::Score ranked(mold::PenaltyVariant variant, double weight, opt::Score* score) {
  mold::MoldSpec spec = mold::load_mold_spec(MTCS_SOURCE_DIR "/molds/plate.yaml");
  spec.penalty.variant = variant;
  spec.penalty.weight = weight;
  const mold::Scene scene(spec);
  const eval::Pipeline pipeline(scene);
  const run::MoldProblem problem(pipeline, {}, {});
  *score = problem.evaluate(problem.encode(through_ejector()));
  return problem.ranking(*score);
}

}  // namespace

TEST_CASE("MoldProblem ranks an infeasible layout as its penalty variant says", "[run][penalty]") {
  opt::Score s;
  const opt::Score cd = ranked(mold::PenaltyVariant::ConstrainedDomination, 1, &s);
  REQUIRE_FALSE(s.feasible);
  REQUIRE(s.violation > 0);
  CHECK_FALSE(cd.feasible);
  CHECK(cd.objectives == s.objectives);
  CHECK(cd.violation == s.violation);

  // The mold's scale of each of its objectives (plate.yaml: temperature_std, temperature_max, cost).
  const mold::MoldSpec spec = mold::load_mold_spec(MTCS_SOURCE_DIR "/molds/plate.yaml");
  std::vector<double> scales;
  for (const auto o : spec.objectives.use) scales.push_back(spec.objectives.scale(o));
  REQUIRE(scales.size() == s.objectives.size());
  const opt::Score linear = ranked(mold::PenaltyVariant::StaticLinear, 3, &s);
  CHECK(linear.feasible);
  CHECK(linear.violation == 0);
  for (std::size_t k = 0; k < 3; ++k)
    CHECK(linear.objectives[k] == Approx(s.objectives[k] + 3 * s.violation * scales[k]).epsilon(1e-14));
  const opt::Score quadratic = ranked(mold::PenaltyVariant::StaticQuadratic, 3, &s);
  for (std::size_t k = 0; k < 3; ++k)
    CHECK(quadratic.objectives[k] == Approx(s.objectives[k] + 3 * s.violation * s.violation * scales[k]).epsilon(1e-14));
  const opt::Score death = ranked(mold::PenaltyVariant::Death, 1, &s);
  CHECK(death.feasible);
  for (const double v : death.objectives) CHECK(std::isinf(v));
}
