// Issue 16, item 3: SMS-EMOA's default reference point fits the mold (a fixed 4 per scaled
// objective gave new molds fronts with hypervolume 0 and no warning), and a front with
// hypervolume 0 or of one design is warned about.

#include <catch2/catch.hpp>

#include "mtcs/opt/sms_emoa.h"
#include "mtcs/run/run_outputs.h"
#include "mtcs/run/session.h"
#include "support/paths.h"

using namespace mtcs;

namespace {

run::RunOverrides sms(long evaluations, std::vector<double> ref = {}) {
  run::RunOverrides o;
  o.algorithm = "sms-emoa";
  o.seed = 3;
  o.evaluations = evaluations;
  o.ref = std::move(ref);
  return o;
}

}  // namespace

TEST_CASE("issue 16: SMS-EMOA's default reference point is twice the worst of the run's own initial population",
          "[run][issue16]") {
  const run::Session session(MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml", sms(400));
  const run::MoldOptimizer optimizer(session.problem(), session.scene(), session.config());
  // The population the run starts from, as the run reports it.
  std::optional<opt::Generation> initial;
  const opt::Generation last = optimizer.run(nullptr, [&](const opt::Generation& g) {
    if (!initial) initial = g;
  });
  REQUIRE(initial);
  std::vector<double> scales;  // the mold's own
  for (const auto o : session.spec().objectives.use) scales.push_back(session.spec().objectives.scale(o));
  REQUIRE(scales.size() == 3);
  std::vector<double> worst(3, 0);
  for (const auto& ind : initial->population)
    for (int k = 0; k < 3; ++k) worst[std::size_t(k)] = std::max(worst[std::size_t(k)], ind.score.objectives[std::size_t(k)] / scales[std::size_t(k)]);
  const auto ref = optimizer.scaled_reference();
  for (int k = 0; k < 3; ++k) CHECK(ref[std::size_t(k)] == Approx(2 * worst[std::size_t(k)]).epsilon(1e-12));
  CHECK_THAT(optimizer.reference_origin(), Catch::Contains("initial population (seed 3"));
  // The front found lies inside it: hypervolume > 0, no warning.
  CHECK(optimizer.scaled_hypervolume(opt::SmsEmoa::front(last)) > 0);
  CHECK(run::front_warnings(optimizer, last).empty());
}

TEST_CASE("issue 16: a front with hypervolume 0 or of a single design is warned about", "[run][issue16]") {
  // A reference point every layout lies beyond.
  const run::Session session(MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml", sms(100, {1e-6, 1e-6, 1e-6}));
  const run::MoldOptimizer optimizer(session.problem(), session.scene(), session.config());
  CHECK_THAT(optimizer.reference_origin(), Catch::Contains("given"));
  opt::Generation last = optimizer.run(nullptr, {});
  REQUIRE_FALSE(opt::SmsEmoa::front(last).empty());
  auto warnings = run::front_warnings(optimizer, last);
  REQUIRE_FALSE(warnings.empty());
  CHECK_THAT(warnings.front(), Catch::Contains("hypervolume is 0"));
  // Ten copies of one feasible design.
  const opt::Individual one = [&] {
    for (const auto& ind : last.population)
      if (ind.score.feasible) return ind;
    return last.population.front();
  }();
  REQUIRE(one.score.feasible);
  for (auto& ind : last.population) ind = one;
  warnings = run::front_warnings(optimizer, last);
  REQUIRE(warnings.size() == 2);
  CHECK_THAT(warnings.back(), Catch::Contains("collapsed to one design"));
}
