// A baffle's and a bubbler's coolant (issue 42, item 5) against hand calculations made another
// way: water from Incropera & DeWitt's Table A.6 (313 K), Haaland's explicit friction factor,
// the passages' areas and hydraulic diameters from the drawing, Dittus-Boelter's film; the rise
// as heat over m c_p in a solve of the plate with a baffle under its cavity.

#include <catch2/catch.hpp>
#include <cmath>

#include "mtcs/eval/cavity_temperature.h"
#include "mtcs/eval/circuit_hydraulics.h"
#include "mtcs/eval/coolant.h"
#include "mtcs/eval/wall_passage.h"
#include "eval/stages.h"
#include "mtcs/mold/decoder.h"
#include "support/bundled_variant.h"

using namespace mtcs;
using geometry::Vec3;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRho = 1 / 1.0082e-3, kMu = 655e-6, kK = 0.631, kPr = 4.34;  // 313 K
constexpr double kRough = 0.045;                                             // mm

// One blind bore, 64 mm from its entry to its tip, as the decoder makes it.
mold::Layout blind(mold::CircuitKind kind, double diameter, double tube_outer = 0, double tube_inner = 0) {
  mold::Bore b{};
  b.flow_start = b.hole.p0 = {0, 0, 0};
  b.flow_end = b.hole.p1 = {0, 0, 64};
  b.diameter = diameter, b.kind = kind, b.tube_outer = tube_outer, b.tube_inner = tube_inner;
  b.drilled_length = 64;
  mold::Layout layout;
  layout.bores.push_back(b);
  return layout;
}

double haaland(double re, double relative_roughness) {
  const double x = -1.8 * std::log10(std::pow(relative_roughness / 3.7, 1.11) + 6.9 / re);
  return 1 / (x * x);
}

struct Duct {
  double v, re, dyn, dh;  // m/s, -, Pa, m
};
Duct duct(double litres_per_minute, double area_mm2, double dh_mm) {
  const double v = litres_per_minute / 60e3 / (area_mm2 * 1e-6);
  return {v, kRho * v * dh_mm * 1e-3 / kMu, kRho * v * v / 2, dh_mm * 1e-3};
}

}  // namespace

TEST_CASE("baffle: the half-disc passage, its drop down and back and its film, against a hand calculation",
          "[eval][hydraulics][baffle]") {
  // 10 mm bore, blade across: a half-disc of pi 10^2 / 8 = 39.27 mm^2, wetted by the 15.71 mm arc
  // and the 10 mm blade: D_h = 4 A / P = 6.110 mm.
  const mold::Layout layout = blind(mold::CircuitKind::Baffle, 10);
  const eval::WallPassage p = eval::wall_passage(layout.bores[0]);
  CHECK(p.area == Approx(39.2699).epsilon(1e-5));
  CHECK(p.hydraulic_diameter == Approx(6.1101).epsilon(1e-4));
  const auto paths = eval::circuit_paths(layout);
  REQUIRE(paths.size() == 1);
  const Duct half = duct(8, 39.2699, 6.1101);
  // Friction over 128 mm (down and back), the 180 degree turn as two right-angle turns (0.99 each),
  // the ports 0.5 + 1.0.
  const double hand = (haaland(half.re, kRough / 6.1101) * 0.128 / half.dh + 2 * 0.99 + 1.5) * half.dyn;
  const eval::PressureDrop drop = eval::pressure_drop(paths[0], 8, eval::water_properties(40), kRough);
  CHECK(drop.velocity == Approx(half.v).epsilon(1e-5));
  CHECK(drop.reynolds == Approx(half.re).epsilon(0.01));
  CHECK(drop.total() == Approx(hand).epsilon(0.05));
  CHECK(drop.turns == Approx(2 * 0.99 * half.dyn).epsilon(0.01));
  // The film on the bore's wall: Dittus-Boelter at D_h (Gnielinski's is within 15 % of it here).
  const double dittus = 0.023 * std::pow(half.re, 0.8) * std::pow(kPr, 0.4) * kK / half.dh;  // W/(m^2 K)
  const double film = eval::wall_film(layout.bores[0], 8, 40) * 1e6;
  CHECK(film == Approx(dittus).epsilon(0.15));
  // More than the same flow gives a plain 10 mm bore (twice the speed in half the area).
  CHECK(film > eval::coolant_film(8, 10, 40) * 1e6 * 1.2);
}

TEST_CASE("bubbler: the tube and the annulus, their drop and the annulus's film, against a hand calculation",
          "[eval][hydraulics][baffle]") {
  // 10 mm bore, a 7 / 5.5 mm tube: the flow up 23.76 mm^2 of tube, back down 40.06 mm^2 of
  // annulus (D_h = 10 - 7 = 3 mm).
  const mold::Layout layout = blind(mold::CircuitKind::Bubbler, 10, 7, 5.5);
  const eval::WallPassage p = eval::wall_passage(layout.bores[0]);
  CHECK(p.area == Approx(40.0553).epsilon(1e-5));
  CHECK(p.hydraulic_diameter == Approx(3));
  const auto paths = eval::circuit_paths(layout);
  const Duct annulus = duct(8, 40.0553, 3), tube = duct(8, 23.7583, 5.5);
  // Friction up 64 mm of tube and down 64 mm of annulus; the jet's exit (1.0 of the tube's dynamic
  // pressure) and the turn into the annulus (0.5 of its); inlet 0.5 at the tube, outlet 1.0 at the annulus.
  const double hand = (haaland(annulus.re, kRough / 3) * 0.064 / annulus.dh + 0.5 + 1.0) * annulus.dyn +
                      (haaland(tube.re, kRough / 5.5) * 0.064 / tube.dh + 1.0 + 0.5) * tube.dyn;
  const eval::PressureDrop drop = eval::pressure_drop(paths[0], 8, eval::water_properties(40), kRough);
  CHECK(drop.velocity == Approx(annulus.v).epsilon(1e-5));
  CHECK(drop.reynolds == Approx(annulus.re).epsilon(0.01));
  CHECK(drop.total() == Approx(hand).epsilon(0.05));
  // The annulus heated at its outer wall: Dittus-Boelter at D_h times Gnielinski's 0.9 - 0.15 a^0.6.
  const double dittus = 0.023 * std::pow(annulus.re, 0.8) * std::pow(kPr, 0.4) * kK / annulus.dh *
                        (0.9 - 0.15 * std::pow(0.7, 0.6));
  CHECK(eval::wall_film(layout.bores[0], 8, 40) * 1e6 == Approx(dittus).epsilon(0.15));
}

TEST_CASE("blind bore: a drilled bore's film and drop are the round tube's, unchanged", "[eval][hydraulics][baffle]") {
  mold::Layout layout = blind(mold::CircuitKind::Drilled, 8);
  CHECK(eval::wall_film(layout.bores[0], 8, 40) == eval::coolant_film(8, 8, 40));
  const auto paths = eval::circuit_paths(layout);
  const eval::WallPassage p = eval::wall_passage(layout.bores[0]);
  CHECK(p.hydraulic_diameter == 8);
  CHECK(p.film_factor == 1);
  CHECK(eval::pressure_drop(paths[0], 8, eval::water_properties(40), kRough).turns == 0);
}

TEST_CASE("blind bore: on the plate, a baffle's coolant warms by its heat over m c_p, its heat alike in both tiers",
          "[eval][hydraulics][baffle][thermal]") {
  const mold::MoldSpec spec = mold::load_mold_spec(mtcs_test::bundled_variant(
      "plate", "  allowed_faces: [+x, -x, +y, -y]\n", "  allowed_faces: [+x, -x, +y, -y]\n  baffles: {faces: [-z]}\n"));
  const mold::Scene scene(spec);
  mold::Genome g;
  g.circuits.push_back({{{70, 0, 80}, {70, 150, 80}, {230, 150, 80}, {230, 0, 80}}, 8});
  g.circuits.push_back({{{150, 100, 0}, {150, 100, 90}}, 10, mold::CircuitKind::Baffle});
  g.circuits.push_back({{{110, 60, 0}, {110, 60, 90}}, 10, mold::CircuitKind::Bubbler});
  const mold::Layout layout = mold::decode(scene, g);
  REQUIRE(layout.bores.size() == 5);
  const eval::WaterProperties water = eval::water_properties(40);
  std::vector<double> blind_heat;
  for (const auto tier : {mold::ThermalTier::T2d, mold::ThermalTier::Fd}) {
    eval::ThermalQuery query = eval::thermal_query(spec);
    query.tier = tier;
    query.cell = 4;
    const eval::CavityTemperature t = eval::cavity_temperature(scene, layout, query);
    const eval::CoolantCircuits& c = t.circuits;
    REQUIRE(c.circuits.size() == 3);
    for (const eval::CircuitHydraulics& k : c.circuits) {
      CHECK(k.heat > 1);  // W: every circuit takes heat from the part
      CHECK(k.rise == Approx(k.heat / eval::capacity_rate(8, water)).epsilon(1e-12));
    }
    CHECK(c.circuits[1].film > c.circuits[0].film);
    blind_heat.push_back(c.circuits[1].heat + c.circuits[2].heat);
  }
  // The line sinks' blind bores (ending inside the steel) against the finite volumes' cells.
  CHECK(blind_heat[0] == Approx(blind_heat[1]).epsilon(0.1));
}

TEST_CASE("blind bore: its cost is its hole's and its insert's (objectives.cost.insert)", "[eval][cost][baffle]") {
  mold::Objectives o;
  const mold::Layout drilled = blind(mold::CircuitKind::Drilled, 10), baffle = blind(mold::CircuitKind::Baffle, 10);
  const double hole = o.cost_setup + o.cost_per_mm * 64;  // 6.4 D deep: no deep-hole surcharge
  CHECK(eval::drilling_cost(drilled, o) == Approx(hole).epsilon(1e-12));
  CHECK(eval::drilling_cost(baffle, o) == Approx(hole + 10).epsilon(1e-12));
  o.cost_insert = 25;
  CHECK(eval::drilling_cost(blind(mold::CircuitKind::Bubbler, 10, 7, 5.5), o) == Approx(hole + 25).epsilon(1e-12));
}
