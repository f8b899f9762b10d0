#include "mtcs/eval/circuit_hydraulics.h"

#include <algorithm>
#include <boost/math/tools/roots.hpp>
#include <cmath>
#include <iomanip>
#include <map>
#include <numbers>
#include <sstream>

namespace mtcs::eval {
namespace {

using std::numbers::pi;
constexpr double kLaminarEnd = 2300, kTurbulentStart = 4000;
constexpr double kLitresPerMinute = 1e-3 / 60;  // m^3/s

double colebrook(double reynolds, double relative_roughness) {
  // Swamee-Jain's explicit start, then Colebrook's fixed point (a contraction: a few steps).
  const double rough = relative_roughness / 3.7;
  double x = -2 * std::log10(rough + 5.74 / std::pow(reynolds, 0.9));  // 1/sqrt(f)
  for (int i = 0; i < 50; ++i) {
    const double next = -2 * std::log10(rough + 2.51 * x / reynolds);
    const bool done = std::abs(next - x) <= 1e-13 * std::abs(x);
    x = next;
    if (done) break;
  }
  return 1 / (x * x);
}

double area(double diameter_mm) {
  const double d = diameter_mm * 1e-3;
  return pi * d * d / 4;
}

std::string regime(double reynolds) {
  if (reynolds < kLaminarEnd) return "laminar";
  return reynolds < 1e4 ? "transitional" : "turbulent";
}

}  // namespace

double darcy_friction(double reynolds, double relative_roughness) {
  if (reynolds <= kLaminarEnd) return 64 / std::max(reynolds, 1e-300);
  if (reynolds >= kTurbulentStart) return colebrook(reynolds, relative_roughness);
  const double s = (reynolds - kLaminarEnd) / (kTurbulentStart - kLaminarEnd);
  return (1 - s) * 64 / kLaminarEnd + s * colebrook(kTurbulentStart, relative_roughness);
}

double turn_loss(double angle) {
  const double s2 = std::pow(std::sin(angle / 2), 2);
  return 0.946 * s2 + 2.047 * s2 * s2;
}

std::vector<CircuitPath> circuit_paths(const mold::Layout& layout) {
  std::map<int, std::vector<int>> by_circuit;
  for (std::size_t i = 0; i < layout.bores.size(); ++i) by_circuit[layout.bores[i].circuit].push_back(int(i));
  std::vector<CircuitPath> paths;
  for (auto& [circuit, bores] : by_circuit) {
    std::sort(bores.begin(), bores.end(), [&](int a, int b) { return layout.bores[a].segment < layout.bores[b].segment; });
    CircuitPath p;
    p.circuit = circuit;
    p.bores = bores;
    const mold::Bore& first = layout.bores[bores.front()];
    p.diameter = first.diameter;
    p.kind = first.kind;
    p.passage = wall_passage(first);
    p.tube_inner = first.tube_inner;
    for (std::size_t k = 0; k < bores.size(); ++k) {
      const mold::Bore& b = layout.bores[bores[k]];
      const geometry::Vec3 along = b.flow_end - b.flow_start;
      p.length += along.norm();
      if (k == 0) continue;
      const mold::Bore& a = layout.bores[bores[k - 1]];
      const geometry::Vec3 before = a.flow_end - a.flow_start;
      const double c = before.dot(along) / std::max(before.norm() * along.norm(), 1e-300);
      p.turns.push_back(std::acos(std::clamp(c, -1.0, 1.0)));
    }
    paths.push_back(std::move(p));
  }
  return paths;
}

namespace {

// A baffle's or bubbler's drop (pressure_drop's comment).
PressureDrop blind_drop(const CircuitPath& path, double litres_per_minute, const WaterProperties& water,
                        double roughness_mm) {
  PressureDrop p;
  const double dh = path.passage.hydraulic_diameter;
  const PassageFlow wall = passage_flow(path.passage, litres_per_minute, water);
  p.velocity = wall.velocity, p.reynolds = wall.reynolds;
  p.friction = darcy_friction(p.reynolds, roughness_mm / dh);
  const double dynamic = water.density * p.velocity * p.velocity / 2;
  const double L = path.length * 1e-3;  // m, entry to tip
  if (path.kind == mold::CircuitKind::Baffle) {
    p.pipe = p.friction * (2 * L / (dh * 1e-3)) * dynamic;
    p.turns = 2 * turn_loss(pi / 2) * dynamic;
    p.ports = (kInletLoss + kOutletLoss) * dynamic;
    return p;
  }
  const double di = path.tube_inner;
  const WallPassage tube{pi * di * di / 4, di, 1};
  const PassageFlow up = passage_flow(tube, litres_per_minute, water);
  const double tube_dynamic = water.density * up.velocity * up.velocity / 2;
  p.pipe = (p.friction * dynamic / (dh * 1e-3) + darcy_friction(up.reynolds, roughness_mm / di) * tube_dynamic / (di * 1e-3)) * L;
  p.turns = 1.0 * tube_dynamic + 0.5 * dynamic;
  p.ports = kInletLoss * tube_dynamic + kOutletLoss * dynamic;
  return p;
}

}  // namespace

PressureDrop pressure_drop(const CircuitPath& path, double litres_per_minute, const WaterProperties& water,
                           double roughness_mm) {
  if (is_blind(path.kind)) return blind_drop(path, litres_per_minute, water, roughness_mm);
  PressureDrop p;
  const double d = path.diameter * 1e-3;
  p.velocity = litres_per_minute * kLitresPerMinute / area(path.diameter);
  p.reynolds = water.density * p.velocity * d / water.viscosity;
  p.friction = darcy_friction(p.reynolds, roughness_mm / path.diameter);
  const double dynamic = water.density * p.velocity * p.velocity / 2;  // Pa
  p.pipe = p.friction * (path.length * 1e-3 / d) * dynamic;
  double turns = 0;
  for (double a : path.turns) turns += turn_loss(a);
  p.turns = turns * dynamic;
  p.ports = (kInletLoss + kOutletLoss) * dynamic;
  return p;
}

double flow_at_pressure(const CircuitPath& path, double pascals, const WaterProperties& water, double roughness_mm) {
  if (!(pascals > 0)) return 0;
  // The drop grows monotonically with the flow (f Q^2 with f falling slower than 1/Q^2): bracket
  // by doubling, then TOMS 748.
  const auto excess = [&](double q) { return pressure_drop(path, q, water, roughness_mm).total() - pascals; };
  double lo = 1e-3, hi = 1;
  while (excess(lo) > 0 && lo > 1e-12) lo /= 16;
  while (excess(hi) < 0 && hi < 1e9) hi *= 2;
  boost::uintmax_t iterations = 200;
  const auto [a, b] = boost::math::tools::toms748_solve(excess, lo, hi, boost::math::tools::eps_tolerance<double>(34),
                                                        iterations);
  return (a + b) / 2;
}

double capacity_rate(double litres_per_minute, const WaterProperties& water) {
  return water.density * litres_per_minute * kLitresPerMinute * water.specific_heat;
}

double pump_pressure(std::span<const std::pair<double, double>> pump, double litres_per_minute) {
  if (pump.empty()) return 0;
  if (litres_per_minute <= pump.front().first) return pump.front().second;
  for (std::size_t i = 1; i < pump.size(); ++i)
    if (litres_per_minute <= pump[i].first) {
      const auto& [q0, p0] = pump[i - 1];
      const auto& [q1, p1] = pump[i];
      return p0 + (p1 - p0) * (litres_per_minute - q0) / (q1 - q0);
    }
  return 0;  // past its curve the pump gives nothing more
}

double pump_operating_pressure(std::span<const CircuitPath> paths, std::span<const std::pair<double, double>> pump,
                               const WaterProperties& water, double roughness_mm) {
  // The pump's pressure at the flow a pressure p drives through all circuits, less p: falling in
  // p (more pressure, more flow, less from the pump). Positive near 0, at most 0 at the pump's
  // highest pressure.
  const auto excess = [&](double p) {
    double total = 0;
    for (const CircuitPath& path : paths) total += flow_at_pressure(path, p, water, roughness_mm);
    return pump_pressure(pump, total) - p;
  };
  const double hi = pump.front().second, lo = 0;  // excess(0) = the pump's first pressure > 0 (the spec's check)
  if (paths.empty() || excess(hi) >= 0) return hi;
  boost::uintmax_t iterations = 200;
  const auto [a, b] =
      boost::math::tools::toms748_solve(excess, lo, hi, boost::math::tools::eps_tolerance<double>(40), iterations);
  return (a + b) / 2;
}

std::vector<double> circuit_flows(std::span<const CircuitPath> paths, const mold::MoldSpec& spec) {
  const mold::ThermalSpec& t = spec.thermal;
  std::vector<double> flows;
  if (t.flow_rate) {
    flows.assign(paths.size(), *t.flow_rate);
  } else if (t.supply_pressure || !t.pump.empty()) {
    const WaterProperties water = water_properties(t.coolant_temperature);
    const double p = t.supply_pressure ? *t.supply_pressure : pump_operating_pressure(paths, t.pump, water, t.roughness);
    for (const CircuitPath& path : paths) flows.push_back(flow_at_pressure(path, p, water, t.roughness));
  }
  return flows;
}

std::vector<double> bore_flows(const mold::Layout& layout, const mold::MoldSpec& spec) {
  const mold::ThermalSpec& t = spec.thermal;
  if (t.flow_rate) return std::vector<double>(layout.bores.size(), *t.flow_rate);
  if (!t.flowing()) return {};
  std::vector<double> flow(layout.bores.size(), 0.0);
  const std::vector<CircuitPath> paths = circuit_paths(layout);
  const std::vector<double> flows = circuit_flows(paths, spec);
  for (std::size_t k = 0; k < paths.size(); ++k)
    for (int b : paths[k].bores) flow[std::size_t(b)] = flows[k];
  return flow;
}

std::string ShopCheck::text() const {
  std::ostringstream s;
  s << "circuit " << circuit << ": ";
  if (what == "reynolds")
    s << std::fixed << std::setprecision(0) << "Reynolds number " << found << ", under " << limit
      << " (thermal.coolant.min_reynolds): the flow is not fully turbulent, its film weak";
  else if (what == "rise")
    s << std::fixed << std::setprecision(2) << "coolant rise " << found << " K, over " << limit
      << " K (thermal.coolant.max_rise): the outlet's end of the circuit cools less";
  else if (what == "balance")
    s << std::fixed << std::setprecision(2) << "heat " << found << " times the circuits' mean, beyond " << limit
      << " (thermal.coolant.balance): the circuits cool unevenly";
  else
    s << std::fixed << std::setprecision(3) << "pressure drop " << found / 1e5 << " bar, over the supply's " << limit / 1e5
      << " bar (thermal.coolant.supply_pressure): the circuit cannot take its flow";
  return s.str();
}

namespace {

// The checks of each circuit's heat (W) and rise (K), one entry per circuit: over max_rise, and
// out of the balance band around the circuits' mean heat (two circuits or more).
void check_heat(std::span<const int> circuit, std::span<const double> heat, std::span<const double> rise,
                const mold::ThermalSpec& t, std::vector<ShopCheck>& out) {
  double all = 0;
  for (double q : heat) all += q;
  const double mean = heat.empty() ? 0 : all / double(heat.size());
  for (std::size_t k = 0; k < circuit.size(); ++k) {
    if (rise[k] > t.max_rise) out.push_back({circuit[k], "rise", rise[k], t.max_rise});
    if (!t.balance || heat.size() < 2 || !(mean > 0)) continue;
    const double ratio = heat[k] / mean;
    if (ratio > 1 + *t.balance) out.push_back({circuit[k], "balance", ratio, 1 + *t.balance});
    else if (ratio < 1 - *t.balance) out.push_back({circuit[k], "balance", ratio, 1 - *t.balance});
  }
}

}  // namespace

CoolantCircuits coolant_circuits(const mold::Layout& layout, const mold::MoldSpec& spec, std::span<const double> bore_heat) {
  const mold::ThermalSpec& t = spec.thermal;
  CoolantCircuits out;
  const std::vector<CircuitPath> paths = circuit_paths(layout);
  const std::vector<double> flows = circuit_flows(paths, spec);
  out.flowing = !flows.empty();
  out.from_supply = !t.flow_rate && (t.supply_pressure || !t.pump.empty());
  out.from_pump = !t.flow_rate && !t.pump.empty();
  if (!out.flowing) return out;
  const WaterProperties water = water_properties(t.coolant_temperature);
  // The pressure the flows were found at: each circuit's drop at its flow (the pump's point solved once).
  if (out.from_supply && !paths.empty()) out.supply = pressure_drop(paths[0], flows[0], water, t.roughness).total();
  const bool heat_known = bore_heat.size() == layout.bores.size();
  double all_heat = 0;
  for (std::size_t k = 0; k < paths.size(); ++k) {
    const CircuitPath& p = paths[k];
    CircuitHydraulics c;
    c.circuit = p.circuit;
    c.bores = int(p.bores.size());
    c.turns = is_blind(p.kind) ? 1 : int(p.turns.size());
    c.kind = p.kind;
    c.diameter = p.diameter;
    c.length = p.length;
    c.flow = flows[k];
    c.drop = pressure_drop(p, c.flow, water, t.roughness);
    c.regime = regime(c.drop.reynolds);
    c.film = wall_film(layout.bores[std::size_t(p.bores.front())], c.flow, t.coolant_temperature) * 1e6;
    c.coolant_in = c.coolant_out = t.coolant_temperature;
    c.heat_known = heat_known;
    if (heat_known) {
      for (int b : p.bores) c.heat += bore_heat[std::size_t(b)];
      c.rise = c.heat / capacity_rate(c.flow, water);
      c.coolant_out = c.coolant_in + c.rise;
      all_heat += c.heat;
    }
    out.total_flow += c.flow;
    out.circuits.push_back(c);
  }
  std::vector<int> ids;
  std::vector<double> heats, rises;
  for (CircuitHydraulics& c : out.circuits) {
    if (heat_known && all_heat != 0) c.heat_share = c.heat / all_heat;
    if (c.drop.reynolds < t.min_reynolds) out.checks.push_back({c.circuit, "reynolds", c.drop.reynolds, t.min_reynolds});
    // With a supply and a given flow the supply is a limit; alone it sets the flow (the drop is it).
    if (t.supply_pressure && t.flow_rate && c.drop.total() > *t.supply_pressure)
      out.checks.push_back({c.circuit, "pressure", c.drop.total(), *t.supply_pressure});
    ids.push_back(c.circuit), heats.push_back(c.heat), rises.push_back(c.rise);
  }
  if (heat_known) check_heat(ids, heats, rises, t, out.checks);
  return out;
}

std::vector<BoreCoolant> bore_coolant(const mold::Layout& layout, const mold::MoldSpec& spec,
                                      std::span<const double> bore_heat) {
  if (bore_heat.size() != layout.bores.size()) return {};
  const std::vector<CircuitPath> paths = circuit_paths(layout);
  const std::vector<double> flows = circuit_flows(paths, spec);
  if (flows.empty()) return {};
  const WaterProperties water = water_properties(spec.thermal.coolant_temperature);
  std::vector<BoreCoolant> out(layout.bores.size());
  for (std::size_t k = 0; k < paths.size(); ++k) {
    const double capacity = capacity_rate(flows[k], water);
    double at = spec.thermal.coolant_temperature;
    for (int b : paths[k].bores) {
      out[std::size_t(b)].in = at;
      at += bore_heat[std::size_t(b)] / capacity;
      out[std::size_t(b)].out = at;
    }
  }
  return out;
}

std::vector<ShopCheck> heat_checks(const mold::Layout& layout, const mold::MoldSpec& spec,
                                   std::span<const double> bore_flow, std::span<const double> bore_heat) {
  const std::size_t n = layout.bores.size();
  if (bore_flow.size() != n || bore_heat.size() != n) return {};
  const WaterProperties water = water_properties(spec.thermal.coolant_temperature);
  // Bores come circuit by circuit (the decoder's order); a map keeps any order right.
  std::map<int, std::pair<double, double>> heat_and_capacity;
  for (std::size_t i = 0; i < n; ++i) {
    auto& [heat, capacity] = heat_and_capacity[layout.bores[i].circuit];
    heat += bore_heat[i];
    capacity = capacity_rate(bore_flow[i], water);
  }
  std::vector<int> ids;
  std::vector<double> heats, rises;
  for (const auto& [circuit, hc] : heat_and_capacity)
    ids.push_back(circuit), heats.push_back(hc.first), rises.push_back(hc.second > 0 ? hc.first / hc.second : 0.0);
  std::vector<ShopCheck> out;
  check_heat(ids, heats, rises, spec.thermal, out);
  return out;
}

}  // namespace mtcs::eval
