// The circuits' hydraulics (issue 42) against hand calculations made another way: water from a
// second table (Incropera), Haaland's explicit friction factor instead of Colebrook's, the
// lengths and turns counted off the drawing; Colebrook against Moody's chart; the flow a supply
// pressure drives against the drop it needs; the coolant's rise against the heat over m c_p in a
// solve of the plate.

#include <catch2/catch.hpp>
#include <cmath>

#include "mtcs/eval/cavity_temperature.h"
#include "mtcs/eval/circuit_hydraulics.h"
#include "mtcs/eval/coolant.h"
#include "mtcs/eval/thermal_model.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "support/bundled_variant.h"
#include "support/paths.h"

using namespace mtcs;
using geometry::Vec3;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A circuit of straight bores through `points` (flow order), one diameter.
mold::Layout chain(const std::vector<Vec3>& points, double diameter, int circuit = 0, mold::Layout layout = {}) {
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    mold::Bore b{};
    b.flow_start = b.hole.p0 = points[i], b.flow_end = b.hole.p1 = points[i + 1];
    b.diameter = diameter, b.circuit = circuit, b.segment = int(i);
    layout.bores.push_back(b);
  }
  return layout;
}

// Six legs of 300 mm joined by five 40 mm steps: 2 m with ten right-angle turns.
std::vector<Vec3> serpentine() {
  std::vector<Vec3> points{{0, 0, 20}};
  for (int leg = 0; leg < 6; ++leg) {
    const Vec3 at = points.back();
    points.push_back({leg % 2 ? 0.0 : 300.0, at.y(), 20});
    if (leg < 5) points.push_back({points.back().x(), at.y() + 40, 20});
  }
  return points;
}

// The hand calculation: water at 40 C from Incropera & DeWitt, Fundamentals of Heat and Mass
// Transfer, Table A.6 (313 K, between 310 and 315 K), Haaland (1983) for the friction factor,
// 0.99 per right-angle drilled turn (Weisbach), 0.5 + 1.0 for the ports.
double hand_drop(double litres_per_minute, double diameter_mm, double length_mm, int right_turns, double roughness_mm) {
  const double rho = 1 / 1.0082e-3, mu = 655e-6;
  const double d = diameter_mm * 1e-3;
  const double v = litres_per_minute / 60e3 / (kPi * d * d / 4);
  const double re = rho * v * d / mu;
  const double x = -1.8 * std::log10(std::pow(roughness_mm / diameter_mm / 3.7, 1.11) + 6.9 / re);
  const double f = 1 / (x * x);
  return (f * length_mm / diameter_mm + 0.99 * right_turns + 1.5) * rho * v * v / 2;
}

// The plate with another coolant line.
mold::MoldSpec spec_with(const std::string& coolant) {
  return mold::load_mold_spec(
      mtcs_test::bundled_variant("plate", "coolant: {temperature: 40, flow_rate: 8}", "coolant: " + coolant));
}

}  // namespace

TEST_CASE("hydraulics: Colebrook's friction factor against Moody's chart and the laminar law", "[eval][hydraulics]") {
  // Smooth tube: 0.0180 at Re 1e5, 0.0116 at 1e6 (Moody 1944; Petukhov's smooth-tube law within 2 %).
  CHECK(eval::darcy_friction(1e5, 0) == Approx(0.0180).epsilon(0.01));
  CHECK(eval::darcy_friction(1e6, 0) == Approx(0.0116).epsilon(0.01));
  CHECK(eval::darcy_friction(1e5, 0) == Approx(eval::petukhov_friction(1e5)).epsilon(0.02));
  // Rough: 0.0222 at e/d = 0.001, Re 1e5; fully rough at e/d = 0.01: von Karman's 0.0379.
  CHECK(eval::darcy_friction(1e5, 0.001) == Approx(0.0222).epsilon(0.01));
  CHECK(eval::darcy_friction(1e8, 0.01) == Approx(0.0379).epsilon(0.01));
  CHECK(eval::darcy_friction(1000, 0.01) == Approx(0.064));
  // Continuous across the transition's ends.
  CHECK(eval::darcy_friction(2300 * (1 + 1e-9), 0.005) == Approx(64 / 2300.0).epsilon(1e-6));
  CHECK(eval::darcy_friction(4000 * (1 - 1e-9), 0.005) == Approx(eval::darcy_friction(4000, 0.005)).epsilon(1e-6));
}

TEST_CASE("hydraulics: a drilled turn's loss by Weisbach, none when straight on", "[eval][hydraulics]") {
  CHECK(eval::turn_loss(0) == 0);
  CHECK(eval::turn_loss(kPi / 2) == Approx(0.946 / 2 + 2.047 / 4));
  CHECK(eval::turn_loss(kPi / 4) < eval::turn_loss(kPi / 2));
}

TEST_CASE("hydraulics: three documented circuits within 5 % of the hand calculation", "[eval][hydraulics]") {
  const eval::WaterProperties water = eval::water_properties(40);
  SECTION("one straight 8 mm bore, 200 mm, 8 l/min") {
    const auto paths = eval::circuit_paths(chain({{0, 20, 20}, {200, 20, 20}}, 8));
    REQUIRE(paths.size() == 1);
    CHECK(paths[0].length == Approx(200));
    CHECK(paths[0].turns.empty());
    const eval::PressureDrop p = eval::pressure_drop(paths[0], 8, water, 0.045);
    CHECK(p.velocity == Approx(2.653).epsilon(1e-3));
    CHECK(p.total() == Approx(hand_drop(8, 8, 200, 0, 0.045)).epsilon(0.05));
  }
  SECTION("a U of 10 mm bores, 150 + 80 + 150 mm, two right-angle turns, 8 l/min") {
    const auto paths = eval::circuit_paths(chain({{0, 20, 20}, {150, 20, 20}, {150, 100, 20}, {0, 100, 20}}, 10));
    REQUIRE(paths[0].turns.size() == 2);
    CHECK(paths[0].length == Approx(380));
    const eval::PressureDrop p = eval::pressure_drop(paths[0], 8, water, 0.045);
    CHECK(p.total() == Approx(hand_drop(8, 10, 380, 2, 0.045)).epsilon(0.05));
  }
  SECTION("2 m of 6 mm bores with ten right-angle turns, 8 l/min: about 2.5 bar") {
    const auto paths = eval::circuit_paths(chain(serpentine(), 6));
    REQUIRE(paths[0].turns.size() == 10);
    CHECK(paths[0].length == Approx(2000));
    const eval::PressureDrop p = eval::pressure_drop(paths[0], 8, water, 0.045);
    const double hand = hand_drop(8, 6, 2000, 10, 0.045);
    CHECK(p.total() == Approx(hand).epsilon(0.05));
    CHECK(p.total() / 1e5 == Approx(2.5).epsilon(0.15));  // the estimate
    CHECK(p.turns == Approx(10 * eval::turn_loss(kPi / 2) * water.density * p.velocity * p.velocity / 2));
  }
}

TEST_CASE("hydraulics: a supply pressure drives each circuit's own flow, the longer circuit less", "[eval][hydraulics]") {
  const eval::WaterProperties water = eval::water_properties(40);
  mold::Layout layout = chain({{0, 20, 20}, {200, 20, 20}}, 8, 0);
  layout = chain({{0, 60, 20}, {200, 60, 20}, {200, 100, 20}, {0, 100, 20}, {0, 140, 20}, {200, 140, 20}}, 8, 1, layout);
  const auto paths = eval::circuit_paths(layout);
  REQUIRE(paths.size() == 2);
  for (const auto& p : paths) {
    const double q = eval::flow_at_pressure(p, 2e5, water, 0.045);
    CHECK(eval::pressure_drop(p, q, water, 0.045).total() == Approx(2e5).epsilon(1e-9));
  }
  CHECK(eval::flow_at_pressure(paths[1], 2e5, water, 0.045) < eval::flow_at_pressure(paths[0], 2e5, water, 0.045));
  // Down to the laminar range, where the drop is linear in the flow.
  const double slow = eval::flow_at_pressure(paths[0], 1.0, water, 0.045);
  CHECK(eval::pressure_drop(paths[0], slow, water, 0.045).total() == Approx(1.0).epsilon(1e-9));
}

TEST_CASE("hydraulics: the spec's supply pressure in bar, each circuit's film from its own flow", "[eval][hydraulics]") {
  const mold::MoldSpec spec = spec_with("{temperature: 40, supply_pressure: 2, roughness: 0.02}");
  CHECK(*spec.thermal.supply_pressure == Approx(2e5));
  CHECK(spec.thermal.roughness == 0.02);
  mold::Layout layout = chain({{0, 20, 20}, {200, 20, 20}}, 8, 0);
  layout = chain({{0, 60, 20}, {200, 60, 20}, {200, 100, 20}, {0, 100, 20}, {0, 140, 20}, {200, 140, 20}}, 8, 1, layout);
  const auto channels = eval::thermal_channels(layout, spec);
  const auto flows = eval::circuit_flows(eval::circuit_paths(layout), spec);
  REQUIRE(flows.size() == 2);
  CHECK(channels[0].film == Approx(eval::coolant_film(flows[0], 8, 40)));
  CHECK(channels[1].film == Approx(eval::coolant_film(flows[1], 8, 40)));
  CHECK(channels[1].film < channels[0].film);
  const eval::CoolantCircuits cc = eval::coolant_circuits(layout, spec);
  CHECK(cc.from_supply);
  CHECK(cc.total_flow == Approx(flows[0] + flows[1]));
  CHECK(cc.circuits[1].drop.total() == Approx(2e5).epsilon(1e-9));
}

TEST_CASE("hydraulics: a flow rate with a supply pressure: a drop over the supply is a shop check", "[eval][hydraulics]") {
  const mold::MoldSpec spec = spec_with("{temperature: 40, flow_rate: 8, supply_pressure: 0.5, min_reynolds: 40000}");
  const eval::CoolantCircuits cc = eval::coolant_circuits(chain(serpentine(), 8), spec);
  REQUIRE(cc.circuits.size() == 1);
  REQUIRE(cc.checks.size() == 2);  // 8 mm at 8 l/min: Re about 32 000, and over 0.5 bar
  CHECK(cc.checks[0].what == "reynolds");
  CHECK(cc.checks[1].what == "pressure");
  CHECK(cc.checks[1].found == Approx(cc.circuits[0].drop.total()));
  CHECK_THAT(cc.checks[1].text(), Catch::Contains("circuit 0") && Catch::Contains("bar"));
}

TEST_CASE("hydraulics: the coolant's rise is the circuit's heat over m c_p, the circuits' heat the bores' in a solve",
          "[eval][hydraulics][thermal]") {
  const mold::Scene scene(mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/plate.yaml"));
  const mold::Layout layout =
      mold::decode(scene, mold::load_layout(MTCS_SOURCE_DIR + "/molds/plate.layout.yaml", scene.spec()));
  for (const auto tier : {mold::ThermalTier::T2d, mold::ThermalTier::Fd}) {
    eval::ThermalQuery query = eval::thermal_query(scene.spec());
    query.tier = tier;
    query.cell = 4;
    const eval::CavityTemperature r = eval::cavity_temperature(scene, layout, query);
    const eval::CoolantCircuits& cc = r.circuits;
    REQUIRE(cc.flowing);
    REQUIRE(r.bore_heat.size() == layout.bores.size());
    double heat = 0, share = 0;
    const eval::WaterProperties water = eval::water_properties(40);
    for (const auto& c : cc.circuits) {
      CHECK(c.heat_known);
      CHECK(c.flow == 8);
      CHECK(c.rise * water.density * (8e-3 / 60) * water.specific_heat == Approx(c.heat).epsilon(1e-6));
      CHECK(c.coolant_out == Approx(40 + c.rise).epsilon(1e-12));
      CHECK(c.rise > 0);
      heat += c.heat, share += c.heat_share;
    }
    CHECK(heat == Approx(r.balance.to_channels).epsilon(1e-9));
    CHECK(share == Approx(1));
  }
}

TEST_CASE("hydraulics: a pump's curve meets the circuits' total flow, found another way", "[eval][hydraulics]") {
  // Two circuits on a pump of 2 bar at no flow falling linearly to 0 at 40 l/min. The test's own
  // route: bisection on the straight circuit's flow q, the long one's flow from the same drop, the
  // pump's pressure at their sum against that drop (mtcs solves on the pressure instead).
  const mold::MoldSpec spec = spec_with("{temperature: 40, pump: [[0, 2], [40, 0]]}");
  REQUIRE(spec.thermal.pump.size() == 2);
  CHECK(spec.thermal.pump[0].second == Approx(2e5));
  mold::Layout layout = chain({{0, 20, 20}, {200, 20, 20}}, 8, 0);
  layout = chain({{0, 60, 20}, {200, 60, 20}, {200, 100, 20}, {0, 100, 20}, {0, 140, 20}, {200, 140, 20}}, 8, 1, layout);
  const auto paths = eval::circuit_paths(layout);
  const eval::WaterProperties water = eval::water_properties(40);
  const auto pump = [](double q) { return 2e5 * (1 - q / 40); };
  double lo = 1e-6, hi = 40;
  for (int i = 0; i < 200; ++i) {
    const double q = (lo + hi) / 2, drop = eval::pressure_drop(paths[0], q, water, 0.045).total();
    const double q_long = eval::flow_at_pressure(paths[1], drop, water, 0.045);
    (pump(q + q_long) > drop ? lo : hi) = q;
  }
  const double drop = eval::pressure_drop(paths[0], lo, water, 0.045).total();
  const auto flows = eval::circuit_flows(paths, spec);
  REQUIRE(flows.size() == 2);
  CHECK(flows[0] == Approx(lo).epsilon(1e-8));
  CHECK(flows[1] == Approx(eval::flow_at_pressure(paths[1], drop, water, 0.045)).epsilon(1e-8));
  const eval::CoolantCircuits cc = eval::coolant_circuits(layout, spec);
  CHECK(cc.from_pump);
  CHECK(cc.supply == Approx(drop).epsilon(1e-8));
  CHECK(cc.supply == Approx(pump(cc.total_flow)).epsilon(1e-8));  // on the curve
  CHECK(eval::pump_pressure(spec.thermal.pump, 10) == Approx(1.5e5));
  CHECK(eval::pump_pressure(spec.thermal.pump, 50) == 0);
  // A pump whose curve ends at 5 l/min, still at 1.9 bar: the circuits get no more than 5 l/min.
  const eval::CoolantCircuits small = eval::coolant_circuits(layout, spec_with("{temperature: 40, pump: [[0, 2], [5, 1.9]]}"));
  CHECK(small.total_flow <= 5 + 1e-6);
  CHECK(small.total_flow > 4.9);
  // The flows drive each bore's film, as a supply pressure's do.
  CHECK(eval::thermal_channels(layout, spec)[1].film == Approx(eval::coolant_film(flows[1], 8, 40)));
  CHECK_THROWS_WITH(spec_with("{temperature: 40, pump: [[0, 2], [40, 3]]}"), Catch::Contains("thermal.coolant.pump[1]"));
  CHECK_THROWS_WITH(spec_with("{temperature: 40, pump: [[0, 2]]}"), Catch::Contains("at least two points"));
  CHECK_THROWS_WITH(spec_with("{temperature: 40, flow_rate: 8, pump: [[0, 2], [40, 0]]}"), Catch::Contains("give pump or flow_rate"));
  CHECK_THROWS_WITH(spec_with("{temperature: 40, pump: [[0, 0], [40, 0]]}"), Catch::Contains("no pressure"));
}

TEST_CASE("hydraulics: the spec's coolant refuses a film with a supply pressure, a pressure of 0, oil with a supply",
          "[eval][hydraulics][spec]") {
  CHECK_THROWS_WITH(spec_with("{temperature: 40, film: 5000, supply_pressure: 2}"),
                    Catch::Contains("plate") && Catch::Contains("give film or supply_pressure"));
  CHECK_THROWS_WITH(spec_with("{temperature: 40, supply_pressure: 0}"), Catch::Contains("thermal.coolant.supply_pressure"));
  CHECK_THROWS_WITH(spec_with("{temperature: 150, supply_pressure: 2}"), Catch::Contains("0 to 106 degrees C"));
  CHECK_THROWS_WITH(spec_with("{temperature: 40, flow_rate: 8, roughness: -1}"), Catch::Contains("thermal.coolant.roughness"));
}
