#pragma once
// The coolant's way through each circuit, as a mold shop checks it (issue 42): the flow a circuit
// takes, its Reynolds number, the pressure it needs (Darcy-Weisbach friction in the drilled bores,
// Weisbach's loss at every drilled turn, the ports), and how much the coolant warms from inlet to
// outlet with the heat the circuit takes (docs/coolant-circuits.md).

#include <span>
#include <string>
#include <vector>

#include "mtcs/eval/coolant.h"
#include "mtcs/eval/wall_passage.h"
#include "mtcs/mold/layout.h"
#include "mtcs/mold/mold_spec.h"

namespace mtcs::eval {

// Darcy's friction factor: 64/Re up to Re = 2300, Colebrook-White (1939) from Re = 4000 (iterated
// to 1e-12), linear in Re in between. relative_roughness: the wall's equivalent sand roughness
// over the diameter (0: a smooth tube, where Colebrook matches Petukhov within 2 %).
double darcy_friction(double reynolds, double relative_roughness);

// The loss coefficient of a sharp (mitred) turn by `angle` radians from straight on, Weisbach's
// 0.946 sin^2(a/2) + 2.047 sin^4(a/2): 0.99 at a right angle. Two drilled bores meet without a
// rounding; the drill point's pocket beyond the corner is not counted (a few tenths more).
double turn_loss(double angle);
// The ports: the coolant enters from a fitting as through a sharp entrance and leaves into a
// wider passage (0.5 and 1.0 dynamic pressures, the textbook values).
inline constexpr double kInletLoss = 0.5, kOutletLoss = 1.0;

// One circuit as the coolant meets it: its bores' flow lengths in flow order, one diameter, the
// turns between consecutive bores. A baffle's or bubbler's: its blind bore, entry to tip (the
// coolant goes down and back), and the insert.
struct CircuitPath {
  int circuit = 0;
  std::vector<int> bores;     // indices into the layout's bores, in flow order
  double diameter = 0;        // mm
  double length = 0;          // mm, the flow's
  std::vector<double> turns;  // radians from straight on, one per junction
  mold::CircuitKind kind = mold::CircuitKind::Drilled;
  WallPassage passage;        // along the bore's wall
  double tube_inner = 0;      // mm, a bubbler's tube (the flow up it)
};
std::vector<CircuitPath> circuit_paths(const mold::Layout& layout);

// The parts of a circuit's pressure drop (Pa) at a flow of `litres_per_minute` of `water`. The
// velocity, Reynolds number and friction factor are the wall passage's (what the film sees). A
// baffle: friction down and back (twice the bore's depth) in its half, the turn around the blade's
// end as two right-angled turns; a bubbler: friction up the tube and down the annulus, the jet's
// exit from the tube (1.0 of the tube's dynamic pressure) and the entry into the annulus (0.5);
// the ports as a drilled circuit's, inlet at the feeding passage's velocity, outlet at the
// returning one's.
struct PressureDrop {
  double velocity = 0, reynolds = 0, friction = 0;  // m/s, -, Darcy's f
  double pipe = 0, turns = 0, ports = 0;            // Pa
  double total() const { return pipe + turns + ports; }
};
PressureDrop pressure_drop(const CircuitPath& path, double litres_per_minute, const WaterProperties& water,
                           double roughness_mm);
// The flow (l/min) at which the circuit's drop equals `pascals` (to 1e-10 relative); 0 at no pressure.
double flow_at_pressure(const CircuitPath& path, double pascals, const WaterProperties& water, double roughness_mm);

// W/K: rho Q c_p of `litres_per_minute` of `water`, what warms it by a kelvin.
double capacity_rate(double litres_per_minute, const WaterProperties& water);

// The pump's pressure (Pa) at a total flow (l/min): linear between the curve's points, 0 past the
// last (the pump gives no more flow than its curve).
double pump_pressure(std::span<const std::pair<double, double>> pump, double litres_per_minute);
// The pressure (Pa) across parallel circuits where the pump's curve meets their total flow: the
// operating point (TOMS 748 on the pressure, each circuit's flow by flow_at_pressure).
double pump_operating_pressure(std::span<const CircuitPath> paths, std::span<const std::pair<double, double>> pump,
                               const WaterProperties& water, double roughness_mm);

// Each circuit's flow (l/min): the spec's flow_rate, or the flow its supply pressure (or the
// pump's operating pressure) drives through it; empty when the spec gives none (a film or a wall
// at the coolant temperature).
std::vector<double> circuit_flows(std::span<const CircuitPath> paths, const mold::MoldSpec& spec);
// Each bore's flow (l/min, the layout's order): its circuit's; empty as circuit_flows is.
std::vector<double> bore_flows(const mold::Layout& layout, const mold::MoldSpec& spec);

struct CircuitHydraulics {
  int circuit = 0, bores = 0, turns = 0;  // a blind bore's one turn: at its tip
  mold::CircuitKind kind = mold::CircuitKind::Drilled;
  double diameter = 0, length = 0;  // mm
  double flow = 0;                  // l/min
  PressureDrop drop;
  std::string regime;               // laminar, transitional, turbulent (Moldflow's bands)
  double film = 0;                  // W/(m^2 K), Gnielinski
  bool heat_known = false;          // the solve's heat per bore was given
  double heat = 0, heat_share = 0;  // W into the coolant, share of all circuits'
  double coolant_in = 0, coolant_out = 0, rise = 0;  // degrees C, K: heat / (rho Q c_p)
};

// A shop's rule a circuit breaks: Reynolds number below thermal.coolant.min_reynolds, a rise above
// max_rise, a drop above the supply pressure, a heat out of the band thermal.coolant.balance
// draws around the circuits' mean (found: the circuit's heat over the mean; limit: the band's
// edge it is beyond).
struct ShopCheck {
  int circuit = 0;
  std::string what;      // reynolds, rise, pressure, balance
  double found = 0, limit = 0;
  std::string text() const;
};

struct CoolantCircuits {
  bool flowing = false;  // the spec gives a flow, a supply pressure or a pump
  bool from_supply = false;  // each circuit's flow follows from the supply pressure or the pump
  bool from_pump = false;
  double supply = 0;         // Pa across each circuit when a pressure drives the flows (the pump's operating point)
  std::vector<CircuitHydraulics> circuits;
  double total_flow = 0;  // l/min, the supply's
  std::vector<ShopCheck> checks;
};

// The circuits of `layout` under the spec's coolant. bore_heat: W into each bore's coolant (the
// layout's order), from a solve; empty: heat and rise unknown (not checked).
CoolantCircuits coolant_circuits(const mold::Layout& layout, const mold::MoldSpec& spec,
                                 std::span<const double> bore_heat = {});

// Each bore's coolant where its flow starts and ends (degrees C, the layout's order): the inlet
// temperature plus the heat taken upstream in its circuit over the circuit's rho Q c_p, as the
// model warms it. Empty when the flow or the heat is not known.
struct BoreCoolant {
  double in = 0, out = 0;
};
std::vector<BoreCoolant> bore_coolant(const mold::Layout& layout, const mold::MoldSpec& spec,
                                      std::span<const double> bore_heat);

// The circuits as `mtcs thermal --json` gives them ("coolant": {flowing, from_supply,
// total_flow, circuits, checks}, SI units), one JSON object as text.
std::string coolant_circuits_json_text(const CoolantCircuits& circuits);

// The checks that need the heat, for a caller that has each bore's flow and heat (the
// temperature stage, after every solve): the circuits whose coolant warms by more than
// thermal.coolant.max_rise, and those out of the thermal.coolant.balance band.
std::vector<ShopCheck> heat_checks(const mold::Layout& layout, const mold::MoldSpec& spec,
                                   std::span<const double> bore_flow, std::span<const double> bore_heat);

}  // namespace mtcs::eval
