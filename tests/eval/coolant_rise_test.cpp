// The coolant warming along its circuits in the model (issue 42, item 2): the line sinks'
// lower-triangular coupling against a second method (the same equations by a fixed point over the
// channels' coolants), the finite volumes' fixed point against the line sinks, and what is
// physically possible (warmer coolant, warmer steel; the outlet at the heat over m c_p).

#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

#include "mtcs/eval/cavity_temperature.h"
#include "mtcs/eval/coolant.h"
#include "mtcs/eval/thermal_model.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/thermal/finite_volume.h"
#include "mtcs/thermal/line_sinks.h"
#include "support/bundled_variant.h"
#include "support/paths.h"

using namespace mtcs;

namespace {

struct Plate {
  mold::Scene scene;
  mold::Layout layout;
};

// The plate's hand-made layout, its coolant at `flow` l/min per circuit.
Plate plate(double flow, bool rise = true) {
  const std::string coolant = "coolant: {temperature: 40, flow_rate: " + std::to_string(flow) +
                              (rise ? "" : ", rise: false") + "}";
  mold::Scene scene(mold::load_mold_spec(
      mtcs_test::bundled_variant("plate", "coolant: {temperature: 40, flow_rate: 8}", coolant)));
  mold::Layout layout =
      mold::decode(scene, mold::load_layout(MTCS_SOURCE_DIR + "/molds/plate.layout.yaml", scene.spec()));
  return {std::move(scene), std::move(layout)};
}

// Each channel cut into `pieces` in flow order, as channels of their own.
std::vector<thermal::Channel> cut(const std::vector<thermal::Channel>& channels, int pieces) {
  std::vector<thermal::Channel> out;
  for (const thermal::Channel& c : channels)
    for (int k = 0; k < pieces; ++k) {
      thermal::Channel p = c;
      const geometry::Vec3 d = c.axis.p1 - c.axis.p0;
      p.axis = {c.axis.p0 + (double(k) / pieces) * d, c.axis.p0 + (double(k + 1) / pieces) * d};
      p.position = c.position + double(k) / pieces;
      out.push_back(p);
    }
  return out;
}

}  // namespace

TEST_CASE("coolant rise: the line sinks' coupled system equals a fixed point over the channels' coolants",
          "[eval][thermal][hydraulics]") {
  // One element per channel: the coupled system's coolant per element is then the fixed point's
  // per channel (the inlet's plus the heat upstream and half its own over rho Q c_p), so the two
  // methods solve the same equations. At 1 l/min the rise is several kelvin: a real test.
  const Plate p = plate(1);
  const thermal::Samples samples = eval::thermal_samples(p.scene);
  for (const auto tier : {thermal::Tier::T1, thermal::Tier::T2d}) {
    thermal::LineSinkOptions options;
    options.tier = tier;
    options.elements = 1;
    options.void_panel = p.scene.spec().thermal.void_panel;
    options.single_precision = false;
    const thermal::LineSinkModel model(eval::thermal_setting(p.scene), samples, options);
    const std::vector<thermal::Channel> coupled = cut(eval::thermal_channels(p.layout, p.scene.spec()), 3);
    REQUIRE(coupled.front().capacity > 0);
    thermal::LineSinkCache cache;
    const thermal::LineSinkSolution direct = model.solve(coupled, cache);

    std::vector<thermal::Channel> fixed = coupled;
    for (auto& c : fixed) c.capacity = 0;
    const thermal::LineSinkSolution constant = model.solve(fixed, cache);
    thermal::LineSinkSolution iterated;
    double change = 1;
    for (int solves = 0; change > 1e-12 && solves < 60; ++solves) {
      iterated = model.solve(fixed, cache);
      change = 0;
      for (std::size_t c = 0; c < fixed.size(); ++c) {
        double heat = iterated.channel_heat[c] / 2;
        for (std::size_t d = 0; d < fixed.size(); ++d)
          if (coupled[d].circuit == coupled[c].circuit && coupled[d].position < coupled[c].position)
            heat += iterated.channel_heat[d];
        const double coolant = coupled[c].coolant + heat / coupled[c].capacity;
        change = std::max(change, std::abs(coolant - fixed[c].coolant));
        fixed[c].coolant = coolant;
      }
    }
    REQUIRE(change <= 1e-12);
    double largest = 0;
    for (std::size_t s = 0; s < direct.temperature.size(); ++s)
      largest = std::max(largest, std::abs(direct.temperature[s] - iterated.temperature[s]));
    CHECK(largest < 1e-8);
    CHECK(fixed.back().coolant - 40 > 2);  // the rise is large here
    // The direction: circuit 0's steel warms more by its last bore (the outlet's leg, its coolant
    // 2 K warmer) than by its first (the inlet's), 30 mm apart and 17 mm under the samples: by
    // 0.22 K in T2d; T1's one strength per channel spreads it (0.03 K).
    const auto nearest = [&](const geometry::Vec3& q) {
      std::size_t best = 0;
      for (std::size_t s = 1; s < samples.points.size(); ++s)
        if ((samples.points[s] - q).norm() < (samples.points[best] - q).norm()) best = s;
      return best;
    };
    std::vector<const mold::Bore*> first_circuit;
    for (const mold::Bore& b : p.layout.bores)
      if (b.circuit == 0) first_circuit.push_back(&b);
    const auto& in = *std::min_element(first_circuit.begin(), first_circuit.end(),
                                       [](auto* x, auto* y) { return x->segment < y->segment; });
    const auto& out = *std::max_element(first_circuit.begin(), first_circuit.end(),
                                        [](auto* x, auto* y) { return x->segment < y->segment; });
    const std::size_t at_in = nearest((in->flow_start + in->flow_end) / 2), at_out = nearest((out->flow_start + out->flow_end) / 2);
    CHECK(direct.temperature[at_out] - constant.temperature[at_out] >
          direct.temperature[at_in] - constant.temperature[at_in] + (tier == thermal::Tier::T2d ? 0.1 : 0.0));
  }
}

TEST_CASE("coolant rise: warmer coolant, warmer steel, the outlet at the heat over m c_p, off by the spec",
          "[eval][thermal][hydraulics]") {
  for (const auto tier : {mold::ThermalTier::T2d, mold::ThermalTier::Fd}) {
    const Plate on = plate(2), off = plate(2, false);
    eval::ThermalQuery query = eval::thermal_query(on.scene.spec());
    query.tier = tier, query.cell = 4;
    const eval::CavityTemperature warm = eval::cavity_temperature(on.scene, on.layout, query);
    const eval::CavityTemperature cold = eval::cavity_temperature(off.scene, off.layout, query);
    INFO("tier " << warm.tier);
    double lowest = 1e300, mean = 0;
    for (std::size_t s = 0; s < warm.at_samples.size(); ++s) {
      lowest = std::min(lowest, warm.at_samples[s] - cold.at_samples[s]);
      mean += (warm.at_samples[s] - cold.at_samples[s]) / double(warm.at_samples.size());
    }
    CHECK(lowest > -1e-6);
    CHECK(mean > 0.1);  // 2 l/min: about a kelvin's rise per circuit
    // Less heat leaves through the warmer coolant (the part is coupled: it gives less too).
    CHECK(warm.balance.to_channels < cold.balance.to_channels);
    CHECK(std::abs(warm.balance.residual()) < 1e-6 * warm.balance.in);
    const eval::WaterProperties water = eval::water_properties(40);
    for (const auto& c : warm.circuits.circuits)
      CHECK(c.coolant_out == Approx(40 + c.heat / (water.density * 2e-3 / 60 * water.specific_heat)).epsilon(1e-9));
  }
}

TEST_CASE("coolant rise: the finite volumes' fixed point and the line sinks' system shift the plate alike",
          "[eval][thermal][hydraulics]") {
  // The rise's effect (warm minus constant coolant, mean over the samples) by the two tiers.
  double shift[2] = {0, 0};
  int k = 0;
  for (const auto tier : {mold::ThermalTier::T2d, mold::ThermalTier::Fd}) {
    const Plate on = plate(2), off = plate(2, false);
    eval::ThermalQuery query = eval::thermal_query(on.scene.spec());
    query.tier = tier, query.cell = 4;
    shift[k++] = eval::cavity_temperature(on.scene, on.layout, query).summary.mean -
                 eval::cavity_temperature(off.scene, off.layout, query).summary.mean;
  }
  CHECK(shift[0] > 0);
  CHECK(shift[1] == Approx(shift[0]).epsilon(0.15));
}
