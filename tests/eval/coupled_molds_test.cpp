// Every bundled mold under the coupled cavity condition (thermal.cavity_condition: coupled): the
// spec's line-sink tier against the finite volumes on the bundled layout, and no steel hotter
// than the part (T_p, the melt) or colder than the coolant and the air, on the bundled layout
// and on random ones the optimiser starts from (bores through the part included).
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "mtcs/eval/cavity_temperature.h"
#include "mtcs/eval/evaluation.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/opt/rng.h"
#include "mtcs/run/session.h"
#include "support/bundled_variant.h"
#include "support/paths.h"

using namespace mtcs;

namespace {

struct CoupledMold {
  const char* name;
  const char* line;       // the spec's line replaced
  const char* coupled;
  double mean_within;     // K: the line sinks' mean against T3 at 2 mm on the bundled layout
};

// The bundled molds are coupled but the thermal block (the fixed-flux reference). One nominal
// cycle (cooling 12 s): the tiers compared on one film, not each at its own cycle's fixed point.
const CoupledMold kMolds[] = {
    {"thermal_block", "heat_flux: 50000", "cavity_condition: coupled\n  cycle: {cooling: 12}", 0.3},
    {"plate", "cycle: {fill: 1, pack: 3, open: 5}", "cycle: {cooling: 12}", 2.0},
    {"cup", "cycle: {fill: 1, pack: 3, open: 5}", "cycle: {cooling: 12}", 2.0},
    {"ribbed_box", "cycle: {fill: 1, pack: 3, open: 5}", "cycle: {cooling: 12}", 3.0},
    {"l_bracket", "cycle: {fill: 1, pack: 3, open: 5}", "cycle: {cooling: 12}", 1.0},
    {"gear", "cycle: {fill: 1, pack: 3, open: 5}", "cycle: {cooling: 12}", 1.0},
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
    const run::Session session(mtcs_test::bundled_variant(m.name, m.line, m.coupled), run::RunOverrides{});
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
  const run::Session session(MTCS_SOURCE_DIR + "/molds/plate.yaml", run::RunOverrides{});
  const mold::Scene& scene = session.scene();
  const mold::Layout layout = mold::decode(scene, session.read_layout(MTCS_SOURCE_DIR + "/molds/plate.layout.yaml"));
  const eval::CavityTemperature r = eval::cavity_temperature(scene, layout, eval::thermal_query(scene.spec()));
  INFO("cycle " << r.cycle_time << " s against the film's " << r.condition.cycle << " s, " << r.cycle_iterations << " solves");
  REQUIRE(r.ejectable);
  CHECK(r.cycle_iterations >= 2);
  CHECK(r.cycle_time == Approx(r.condition.cycle).epsilon(0.01));
  CHECK(r.cycle_time == Approx(r.cooling_time + 1 + 3 + 5).epsilon(1e-12));
  // A cycle the spec fixes is kept: one solve.
  const run::Session fixed(mtcs_test::bundled_variant("plate", "cycle: {fill: 1, pack: 3, open: 5}", "cycle: {cooling: 15}"),
                           run::RunOverrides{});
  const eval::CavityTemperature once = eval::cavity_temperature(fixed.scene(), layout, eval::thermal_query(fixed.spec()));
  CHECK(once.cycle_iterations == 1);
  CHECK(once.condition.cycle == Approx(24));
}

TEST_CASE("coupled cavity: a wall the part cannot set against is infeasible, with the place", "[eval][coupling]") {
  // The cup's hand-made layout leaves its core at ~129 C, above the 90 C the part is ejected at.
  const run::Session session(MTCS_SOURCE_DIR + "/molds/cup.yaml", run::RunOverrides{});
  const mold::Scene& scene = session.scene();
  const mold::ThermalSpec& t = scene.spec().thermal;
  const mold::Genome genome = session.read_layout(MTCS_SOURCE_DIR + "/molds/cup.layout.yaml");
  const eval::Evaluation e = session.pipeline().evaluate(genome);
  const eval::CavityTemperature r =
      eval::cavity_temperature(scene, mold::decode(scene, genome), eval::thermal_query(scene.spec()));
  REQUIRE_FALSE(r.ejectable);
  REQUIRE(e.violations.size() == 1);
  const eval::Violation& v = e.violations[0];
  CHECK(v.kind == eval::ViolationKind::Eject);
  CHECK(v.distance == Approx(r.summary.max).epsilon(1e-9));
  CHECK(v.margin == t.polymer.eject_temperature);
  CHECK((v.where - r.hottest).norm() < 1e-9);
  CHECK(v.amount == Approx((r.summary.max - 90) / (90 - 40)).epsilon(1e-9));
  CHECK(e.violation == Approx(v.amount * v.amount));
  // The optimiser's shortcut (no solve for a layout it cannot build) solves this buildable one:
  // the same score.
  const eval::Evaluation skipped = session.pipeline().evaluate_if_feasible(genome);
  CHECK(skipped.violation == e.violation);
  CHECK(skipped.objectives == e.objectives);
  // A layout that breaks a clearance keeps its eject verdict (else a layout could escape it by
  // breaking a clearance a little); the path that skips the solve has its clearances alone.
  mold::Genome broken = genome;
  for (geometry::Vec3& p : broken.circuits[0].waypoints) p.z() = 6;  // the first circuit 2 mm from the bottom face
  const eval::Evaluation b = session.pipeline().evaluate(broken), bs = session.pipeline().evaluate_if_feasible(broken);
  REQUIRE_FALSE(b.feasible());
  REQUIRE(b.violations.size() >= 2);
  CHECK(b.violations[0].kind == eval::ViolationKind::Eject);
  CHECK(bs.violations.size() == b.violations.size() - 1);
  // No bore at all: the mold goes to the part's temperature, and the part never sets.
  const eval::Evaluation none = session.pipeline().evaluate(mold::Genome{});
  REQUIRE(none.violations.size() == 1);
  CHECK(none.violations[0].kind == eval::ViolationKind::Eject);
  CHECK(none.violations[0].distance == t.polymer.melt_temperature);
  CHECK(bs.violation == Approx(b.violation - b.violations[0].amount * b.violations[0].amount));
}

TEST_CASE("coupled cavity: the optimiser's cycle from one solve is the fixed point's", "[eval][coupling]") {
  // The pipeline solves once with the nominal film and follows the cycle on its samples
  // (eval::follow_cycle); mtcs thermal re-solves with each cycle's film. The L-bracket's 6 mm
  // walls move furthest from the nominal cycle (61 s with the wall at the coolant, ~97 s needed).
  for (const char* name : {"plate", "l_bracket"}) {
    INFO(name);
    const run::Session session(MTCS_SOURCE_DIR + "/molds/" + name + ".yaml", run::RunOverrides{});
    const mold::Scene& scene = session.scene();
    const auto& use = scene.spec().objectives.use;
    const std::size_t cycle = std::size_t(std::find(use.begin(), use.end(), mold::Objective::CycleTime) - use.begin()),
                      spread = std::size_t(std::find(use.begin(), use.end(), mold::Objective::TemperatureStd) - use.begin());
    REQUIRE(cycle < use.size());
    std::vector<mold::Genome> layouts{session.read_layout(MTCS_SOURCE_DIR + "/molds/" + name + ".layout.yaml")};
    opt::Rng rng(6122026);
    while (layouts.size() < 4) layouts.push_back(session.problem().genome(session.problem().sample(rng)));
    int compared = 0;
    for (std::size_t k = 0; k < layouts.size(); ++k) {
      const mold::Layout layout = mold::decode(scene, layouts[k]);
      if (layout.bores.empty()) continue;
      const eval::CavityTemperature fixed = eval::cavity_temperature(scene, layout, eval::thermal_query(scene.spec()));
      if (!fixed.ejectable) continue;
      const eval::Evaluation e = session.pipeline().evaluate(layout);
      INFO("layout " << k << ": cycle " << e.objectives[cycle] << " s against " << fixed.cycle_time << " s after "
                     << fixed.cycle_iterations << " solves; std " << e.objectives[spread] << " against "
                     << fixed.summary.std << " K");
      CHECK(e.objectives[cycle] == Approx(fixed.cycle_time).epsilon(0.05));
      CHECK(e.objectives[spread] == Approx(fixed.summary.std).epsilon(0.08));
      ++compared;
    }
    CHECK(compared >= 2);
  }
}

TEST_CASE("cost_per_part: the drilling cost over the lot plus the machine's time for the cycle", "[eval][coupling]") {
  const std::string spec = mtcs_test::bundled_variant(
      "plate", "use: [temperature_std, cycle_time, cost]",
      "use: [cost_per_part, cycle_time, cost]\n  production: {parts: 50000, machine_rate: 72}");
  const run::Session session(spec, run::RunOverrides{});
  const mold::Genome genome = session.read_layout(MTCS_SOURCE_DIR + "/molds/plate.layout.yaml");
  const eval::Evaluation e = session.pipeline().evaluate(genome);
  REQUIRE(e.objectives.size() == 3);
  // 72 per hour is 0.02 per second of cycle.
  CHECK(e.objectives[0] == Approx(e.objectives[2] / 50000 + 0.02 * e.objectives[1]).epsilon(1e-12));
  CHECK(e.objectives[1] > 20);
}

TEST_CASE("temperature_difference: the core/cavity difference mtcs thermal reports, as an objective", "[eval][coupling]") {
  // One fixed cycle, so that the pipeline and mtcs thermal solve with the same film.
  const std::string spec = mtcs_test::bundled_variant(
      "plate", {{"use: [temperature_std, cycle_time, cost]", "use: [temperature_difference, temperature_std, cost]"},
                {"cycle: {fill: 1, pack: 3, open: 5}", "cycle: {fill: 1, pack: 3, open: 5, cooling: 15}"}});
  const run::Session session(spec, run::RunOverrides{});
  const mold::Scene& scene = session.scene();
  const mold::Genome genome = session.read_layout(MTCS_SOURCE_DIR + "/molds/plate.layout.yaml");
  const eval::Evaluation e = session.pipeline().evaluate(genome);
  const eval::CavityTemperature r =
      eval::cavity_temperature(scene, mold::decode(scene, genome), eval::thermal_query(scene.spec()));
  INFO("objective " << e.objectives[0] << " K, mtcs thermal " << r.across.mean << " K over " << r.across.pairs << " pairs");
  REQUIRE(r.across.pairs > 100);
  CHECK(r.across.mean > 1);
  CHECK(e.objectives[0] == Approx(r.across.mean).epsilon(1e-4));
  // The points across the part leave the samples' own objectives as they were, but for the line
  // sinks' float rounding (their coordinates and far-field chunks follow the set of points).
  CHECK(e.objectives[1] == Approx(r.summary.std).epsilon(1e-4));
  // With the cycle followed (the bundled plate's), the samples alone still decide it.
  const run::Session followed(mtcs_test::bundled_variant("plate", "use: [temperature_std, cycle_time, cost]",
                                                         "use: [temperature_std, cycle_time, temperature_difference]"),
                              run::RunOverrides{});
  const run::Session bundled(MTCS_SOURCE_DIR + "/molds/plate.yaml", run::RunOverrides{});
  const eval::Evaluation f = followed.pipeline().evaluate(genome), b = bundled.pipeline().evaluate(genome);
  CHECK(f.objectives[0] == Approx(b.objectives[0]).epsilon(1e-4));
  CHECK(f.objectives[1] == Approx(b.objectives[1]).epsilon(1e-6));
  CHECK(f.objectives[2] > 1);
}

// Issue 45, item 1 (and issue 40's "the score rewards a hotter mold"): on a new part the fixed
// flux's default score improved from 68.77 to 57.41 when the loop over the lid was deleted, while
// the finite-volume mean rose from 148 to 214 C. With the part coupled and cycle_time in every
// bundled mold's objectives, taking any circuit away from the hand-made layout makes the mold
// hotter and its default score worse.
TEST_CASE("default objectives: taking a circuit away from a bundled layout heats the mold and worsens its score",
          "[eval][coupling][issue45]") {
  for (const char* name : {"plate", "cup", "ribbed_box", "l_bracket", "gear"}) {
    INFO(name);
    const run::Session session(MTCS_SOURCE_DIR + "/molds/" + name + ".yaml", run::RunOverrides{});
    const mold::Scene& scene = session.scene();
    const std::vector<std::string>& use = session.objective_names();
    REQUIRE(std::find(use.begin(), use.end(), "cycle_time") != use.end());
    const mold::Genome bundled = session.read_layout(MTCS_SOURCE_DIR + "/molds/" + name + ".layout.yaml");
    const eval::ThermalQuery tier = eval::thermal_query(scene.spec());
    auto score = [&](const mold::Genome& g) { return eval::scalar_fitness(session.pipeline().evaluate(g), scene.spec(), {}); };
    auto mean = [&](const mold::Genome& g) { return eval::cavity_temperature(scene, mold::decode(scene, g), tier).summary.mean; };
    const double score0 = score(bundled), mean0 = mean(bundled);
    REQUIRE(bundled.circuits.size() >= 2);
    for (std::size_t drop = 0; drop < bundled.circuits.size(); ++drop) {
      mold::Genome fewer = bundled;
      fewer.circuits.erase(fewer.circuits.begin() + std::ptrdiff_t(drop));
      INFO("without circuit " << drop);
      CHECK(mean(fewer) > mean0);
      CHECK(score(fewer) > score0);
    }
  }
}
