// Every bundled mold under the coupled cavity condition (thermal.cavity_condition: coupled): the
// spec's line-sink tier against the finite volumes on the bundled layout, and no steel hotter
// than the part (T_p, the melt) or colder than the coolant and the air, on the bundled layout
// and on random ones the optimiser starts from (bores through the part included).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "mtcs/eval/cavity_temperature.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/opt/rng.h"
#include "mtcs/run/session.h"
#include "support/bundled_variant.h"
#include "support/paths.h"

using namespace mtcs;

namespace {

struct CoupledMold {
  const char* name;
  const char* flux_line;  // the spec's line the coupled condition replaces
  const char* coupled;
  double mean_within;     // K: the line sinks' mean against T3 at 2 mm on the bundled layout
};

// The plate's box cavity takes the void as a surface under the coupled condition (the plane cut
// carries a fixed flux only). One nominal cycle (cooling 12 s): the tiers compared on one film,
// not each at its own cycle's fixed point.
const CoupledMold kMolds[] = {
    {"thermal_block", "heat_flux: 50000", "cavity_condition: coupled\n  cycle: {cooling: 12}", 0.3},
    {"plate", "heat_flux: 29000", "cavity_condition: coupled\n  cycle: {cooling: 12}\n  cavity_void: surface\n  void_panel: 12", 2.0},
    {"cup", "heat_flux: 35000", "cavity_condition: coupled\n  cycle: {cooling: 12}", 2.0},
    {"ribbed_box", "heat_flux: 35000", "cavity_condition: coupled\n  cycle: {cooling: 12}", 3.0},
    {"l_bracket", "heat_flux: 15000", "cavity_condition: coupled\n  cycle: {cooling: 12}", 1.0},
    {"gear", "heat_flux: 17000", "cavity_condition: coupled\n  cycle: {cooling: 12}", 1.0},
};

// Every temperature within [coldest, T_p]: the maximum principle of a conduction problem whose
// boundaries all link to one of those temperatures.
void check_bounds(const eval::CavityTemperature& r, double coldest, double part) {
  const auto [lo, hi] = std::minmax_element(r.at_samples.begin(), r.at_samples.end());
  INFO("tier " << r.tier << ": samples from " << *lo << " to " << *hi << " C; bounds " << coldest << " to " << part);
  CHECK(*hi <= part);
  CHECK(*lo >= coldest - 1e-6);
}

}  // namespace

TEST_CASE("coupled cavity: every bundled mold, the line sinks as T3 finds, no steel above the part", "[eval][coupling]") {
  for (const CoupledMold& m : kMolds) {
    INFO(m.name);
    const run::Session session(mtcs_test::bundled_variant(m.name, m.flux_line, m.coupled), run::RunOverrides{});
    const mold::Scene& scene = session.scene();
    const mold::ThermalSpec& t = scene.spec().thermal;
    REQUIRE(t.cavity_condition == mold::CavityCondition::Coupled);
    const double part = t.polymer.melt_temperature, coldest = std::min(t.coolant_temperature, t.ambient_temperature);
    const mold::Layout bundled =
        mold::decode(scene, session.read_layout(MTCS_SOURCE_DIR + "/molds/" + m.name + ".layout.yaml"));
    const eval::ThermalQuery spec_tier = eval::thermal_query(scene.spec());
    eval::ThermalQuery fd = spec_tier;
    fd.tier = mold::ThermalTier::Fd;
    fd.cell = 2;
    const eval::CavityTemperature ls = eval::cavity_temperature(scene, bundled, spec_tier);
    const eval::CavityTemperature reference = eval::cavity_temperature(scene, bundled, fd);
    INFO("line sinks: mean " << ls.summary.mean << ", max " << ls.summary.max << ", heat " << ls.balance.in
                             << " W; T3: " << reference.summary.mean << ", " << reference.summary.max << ", "
                             << reference.balance.in << " W");
    CHECK(ls.condition.model == "coupled");
    CHECK(std::abs(ls.summary.mean - reference.summary.mean) < m.mean_within);
    CHECK(ls.balance.in == Approx(reference.balance.in).epsilon(0.04));
    CHECK(std::abs(ls.balance.residual()) < 1e-6 * ls.balance.in);
    check_bounds(ls, coldest, part);
    check_bounds(reference, coldest, part);
    // Random layouts, as the optimiser's first generation draws them.
    opt::Rng rng(20261206);
    fd.cell = 4;
    for (int k = 0; k < 3; ++k) {
      const mold::Layout layout = mold::decode(scene, session.problem().genome(session.problem().sample(rng)));
      if (layout.bores.empty()) continue;
      INFO("random layout " << k);
      check_bounds(eval::cavity_temperature(scene, layout, spec_tier), coldest, part);
      check_bounds(eval::cavity_temperature(scene, layout, fd), coldest, part);
    }
  }
}

TEST_CASE("coupled cavity: the cycle mtcs thermal reports is the one its film was derived for", "[eval][coupling]") {
  // The plate's layout needs 17.6 s of cooling at its hottest sample, not the nominal 15.1 s (the
  // wall at the coolant): the film follows, and the two agree within 1 % after a few solves.
  const run::Session session(mtcs_test::bundled_variant("plate", "heat_flux: 29000", "cavity_condition: coupled"),
                             run::RunOverrides{});
  const mold::Scene& scene = session.scene();
  const mold::Layout layout = mold::decode(scene, session.read_layout(MTCS_SOURCE_DIR + "/molds/plate.layout.yaml"));
  const eval::CavityTemperature r = eval::cavity_temperature(scene, layout, eval::thermal_query(scene.spec()));
  INFO("cycle " << r.cycle_time << " s against the film's " << r.condition.cycle << " s, " << r.cycle_iterations << " solves");
  REQUIRE(r.ejectable);
  CHECK(r.cycle_iterations >= 2);
  CHECK(r.cycle_time == Approx(r.condition.cycle).epsilon(0.01));
  CHECK(r.cycle_time == Approx(r.cooling_time + 1 + 3 + 5).epsilon(1e-12));
  // A cycle the spec fixes is kept: one solve.
  const run::Session fixed(mtcs_test::bundled_variant("plate", "heat_flux: 29000", "cavity_condition: coupled\n  cycle: {cooling: 15}"),
                           run::RunOverrides{});
  const eval::CavityTemperature once = eval::cavity_temperature(fixed.scene(), layout, eval::thermal_query(fixed.spec()));
  CHECK(once.cycle_iterations == 1);
  CHECK(once.condition.cycle == Approx(24));
}
