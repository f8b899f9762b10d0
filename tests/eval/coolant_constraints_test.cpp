// The shop's limits on the coolant as constraints of the evaluation (issue 42 item 4): a circuit
// below the minimum Reynolds number, over the supply pressure or warming its coolant by more
// than the limit is a violation of that circuit with the number found, as a clearance is; the
// Reynolds number against a hand calculation with water from another table, the drop against
// the hydraulics' own, the rise against the heat the evaluation's solve puts into each bore.

#include <catch2/catch.hpp>
#include <cmath>
#include <map>

#include "mtcs/eval/cavity_temperature.h"
#include "mtcs/eval/circuit_hydraulics.h"
#include "mtcs/eval/coolant.h"
#include "mtcs/eval/pipeline.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "support/bundled_variant.h"
#include "support/paths.h"

using namespace mtcs;

namespace {

constexpr double kPi = 3.14159265358979323846;
const std::string kCoolant = "coolant: {temperature: 40, flow_rate: 8}";

struct Plate {
  explicit Plate(const std::string& coolant)
      : scene(mold::load_mold_spec(mtcs_test::bundled_variant("plate", kCoolant, coolant))),
        pipeline(scene),
        layout(mold::decode(scene, mold::load_layout(MTCS_SOURCE_DIR + "/molds/plate.layout.yaml", scene.spec()))) {}
  mold::Scene scene;
  eval::Pipeline pipeline;
  mold::Layout layout;
};

std::map<std::string, const eval::Violation*> of_kind(const eval::Evaluation& e, eval::ViolationKind kind) {
  std::map<std::string, const eval::Violation*> out;
  for (const auto& v : e.violations)
    if (v.kind == kind) out[v.elements.at(0)] = &v;
  return out;
}

}  // namespace

TEST_CASE("coolant constraints: a circuit under the minimum Reynolds number is a violation of that circuit, found by hand",
          "[eval][hydraulics]") {
  const Plate plate("coolant: {temperature: 40, flow_rate: 2}");
  const eval::Evaluation e = plate.pipeline.evaluate(plate.layout);
  const auto low = of_kind(e, eval::ViolationKind::CoolantReynolds);
  REQUIRE(low.size() == 3);  // the plate's three circuits of 8 mm bores
  // By hand: water at 40 C from Incropera & DeWitt Table A.6 (313 K).
  const double rho = 1 / 1.0082e-3, mu = 655e-6, d = 8e-3;
  const double re = rho * (2e-3 / 60) / (kPi * d * d / 4) * d / mu;
  for (const auto& [circuit, v] : low) {
    CHECK(v->distance == Approx(re).epsilon(0.01));
    CHECK(v->margin == 1e4);
    CHECK(v->amount == Approx((1e4 - v->distance) / 1e4).epsilon(1e-12));
    CHECK(std::string(eval::to_string(v->kind)) == "coolant_reynolds");
  }
  CHECK(low.count("c0") + low.count("c1") + low.count("c2") == 3);
  // At its inlet: the first bore's flow start.
  const mold::Bore* first = nullptr;
  for (const auto& b : plate.layout.bores)
    if (b.circuit == 0 && (!first || b.segment < first->segment)) first = &b;
  CHECK((low.at("c0")->where - first->flow_start).norm() == 0);
  CHECK_FALSE(e.feasible());
  // A constraint without the solve: the feasibility check alone finds it too.
  CHECK(of_kind(plate.pipeline.constraints(plate.layout), eval::ViolationKind::CoolantReynolds).size() == 3);
  // The shop's limit lowered under the flow's: none.
  const Plate laminar_ok("coolant: {temperature: 40, flow_rate: 2, min_reynolds: 5000}");
  CHECK(of_kind(laminar_ok.pipeline.evaluate(laminar_ok.layout), eval::ViolationKind::CoolantReynolds).empty());
}

TEST_CASE("coolant constraints: a drop over the supply pressure is a violation with the circuit's drop", "[eval][hydraulics]") {
  const Plate plate("coolant: {temperature: 40, flow_rate: 8, supply_pressure: 0.1}");
  const eval::Evaluation e = plate.pipeline.evaluate(plate.layout);
  const auto over = of_kind(e, eval::ViolationKind::CoolantPressure);
  const eval::CoolantCircuits cc = eval::coolant_circuits(plate.layout, plate.scene.spec());
  REQUIRE(cc.circuits.size() == 3);
  REQUIRE(over.size() == 3);  // 0.17-0.18 bar each (mtcs evaluate's table), over 0.1 bar
  for (const auto& c : cc.circuits) {
    const eval::Violation& v = *over.at("c" + std::to_string(c.circuit));
    CHECK(v.distance == c.drop.total());
    CHECK(v.margin == Approx(1e4));  // Pa
    CHECK(v.amount == Approx(c.drop.total() / 1e4 - 1).epsilon(1e-12));
  }
  // The supply alone sets each circuit's flow: its drop is the supply, never over it.
  const Plate driven("coolant: {temperature: 40, supply_pressure: 0.1}");
  CHECK(of_kind(driven.pipeline.evaluate(driven.layout), eval::ViolationKind::CoolantPressure).empty());
}

TEST_CASE("coolant constraints: a coolant rise over the limit, the circuit's heat from the evaluation's own solve",
          "[eval][hydraulics][thermal]") {
  const Plate plate("coolant: {temperature: 40, flow_rate: 8, max_rise: 0.3}");
  const eval::Evaluation e = plate.pipeline.evaluate(plate.layout);
  REQUIRE(e.bore_heat.size() == plate.layout.bores.size());
  const eval::WaterProperties water = eval::water_properties(40);
  const double capacity = water.density * (8e-3 / 60) * water.specific_heat;  // W/K
  std::map<int, double> heat;
  for (std::size_t i = 0; i < e.bore_heat.size(); ++i) heat[plate.layout.bores[i].circuit] += e.bore_heat[i];
  const auto over = of_kind(e, eval::ViolationKind::CoolantRise);
  REQUIRE_FALSE(over.empty());
  for (const auto& [circuit, q] : heat) {
    const double rise = q / capacity;
    INFO("circuit " << circuit << ": " << q << " W, " << rise << " K");
    CHECK(over.count("c" + std::to_string(circuit)) == (rise > 0.3 ? 1u : 0u));
    if (rise > 0.3) CHECK(over.at("c" + std::to_string(circuit))->distance == Approx(rise).epsilon(1e-12));
  }
  // The same heat as mtcs thermal finds, which re-solves at the cycle the layout needs where the
  // evaluation rescales its one solve (follow_cycle): within 1 % per circuit (0.4 % on the bundled layout).
  const eval::CavityTemperature shown = eval::cavity_temperature(plate.scene, plate.layout, eval::thermal_query(plate.scene.spec()));
  for (const auto& c : shown.circuits.circuits) {
    INFO("circuit " << c.circuit << ": mtcs thermal " << c.heat << " W, the evaluation " << heat[c.circuit] << " W");
    CHECK(heat[c.circuit] == Approx(c.heat).epsilon(0.01));
  }
  // A rise is a thermal verdict: the feasibility check alone (no solve) does not have it.
  CHECK(of_kind(plate.pipeline.constraints(plate.layout), eval::ViolationKind::CoolantRise).empty());
  // Within the default 3 K: feasible, and the heat still reported.
  const Plate bundled(kCoolant);
  const eval::Evaluation ok = bundled.pipeline.evaluate(bundled.layout);
  CHECK(ok.feasible());
  CHECK(ok.bore_heat.size() == bundled.layout.bores.size());
}

TEST_CASE("coolant constraints: a circuit taking more heat than the balance band allows", "[eval][hydraulics][thermal]") {
  // The plate's three U loops take 176, 206 and 177 W (mtcs evaluate): the middle one 1.106 times
  // the mean, the others 0.944 and 0.95. A band of 8 %: the middle one only.
  const Plate plate("coolant: {temperature: 40, flow_rate: 8, balance: 0.08}");
  const eval::Evaluation e = plate.pipeline.evaluate(plate.layout);
  std::map<int, double> heat;
  for (std::size_t i = 0; i < e.bore_heat.size(); ++i) heat[plate.layout.bores[i].circuit] += e.bore_heat[i];
  REQUIRE(heat.size() == 3);
  const double mean = (heat[0] + heat[1] + heat[2]) / 3;
  const auto out = of_kind(e, eval::ViolationKind::CoolantBalance);
  REQUIRE(out.size() == 1);
  CHECK(out.count("c1") == 1);
  CHECK(out.at("c1")->distance == Approx(heat[1] / mean).epsilon(1e-12));
  CHECK(out.at("c1")->margin == Approx(1.08));
  // Wider, none; no balance key, none either.
  const Plate wide("coolant: {temperature: 40, flow_rate: 8, balance: 0.2}");
  CHECK(of_kind(wide.pipeline.evaluate(wide.layout), eval::ViolationKind::CoolantBalance).empty());
}

TEST_CASE("coolant constraints: no coolant stage without a flow, none of its violations", "[eval][hydraulics]") {
  const mold::Scene scene(mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/thermal_block.yaml"));
  const eval::Pipeline pipeline(scene);
  for (const auto& name : pipeline.stage_names()) CHECK(name != "coolant");
  const Plate plate(kCoolant);
  const auto names = plate.pipeline.stage_names();
  CHECK(std::find(names.begin(), names.end(), "coolant") != names.end());
}
