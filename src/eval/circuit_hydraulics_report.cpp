#include "circuit_hydraulics_report.h"

#include <iomanip>
#include <sstream>

namespace mtcs::eval {

// One row per circuit; the drop in bar, the film in W/(m^2 K) as thermal.coolant.film takes it.
std::string coolant_circuits_text(const CoolantCircuits& cc) {
  if (!cc.flowing) return "";
  std::ostringstream s;
  s << "coolant circuits (water " << std::fixed << std::setprecision(2);
  if (cc.from_pump) s << "from the pump at its operating point, " << cc.supply / 1e5 << " bar";
  else if (cc.from_supply) s << "driven by the supply pressure, " << cc.supply / 1e5 << " bar";
  else s << "at the spec's flow rate";
  s << ", total " << cc.total_flow << " l/min)\n"
    << "  circuit bores turns  d mm  length mm   l/min   m/s  Reynolds regime        drop bar  heat W  share  out degC  rise K  film W/(m^2 K)\n";
  for (const CircuitHydraulics& c : cc.circuits) {
    s << "  " << std::setw(7) << c.circuit << std::setw(6) << c.bores << std::setw(6) << c.turns << std::setprecision(1)
      << std::setw(6) << c.diameter << std::setw(11) << c.length << std::setprecision(2) << std::setw(8) << c.flow
      << std::setw(6) << c.drop.velocity << std::setprecision(0) << std::setw(10) << c.drop.reynolds << " "
      << std::left << std::setw(13) << c.regime << std::right << std::setprecision(3) << std::setw(10)
      << c.drop.total() / 1e5;
    if (c.heat_known)
      s << std::setprecision(1) << std::setw(8) << c.heat << std::setprecision(0) << std::setw(6) << 100 * c.heat_share
        << "%" << std::setprecision(2) << std::setw(10) << c.coolant_out << std::setw(8) << c.rise;
    else
      s << std::setw(8) << "-" << std::setw(7) << "-" << std::setw(10) << "-" << std::setw(8) << "-";
    s << std::setprecision(0) << std::setw(16) << c.film;
    if (is_blind(c.kind)) s << "  (" << mold::to_string(c.kind) << ")";
    s << "\n";
  }
  if (cc.checks.empty()) s << "  shop checks passed (Reynolds, coolant rise, pressure drop, balance)\n";
  for (const ShopCheck& c : cc.checks) s << "  shop check: " << c.text() << "\n";
  return s.str();
}

nlohmann::ordered_json coolant_circuits_json(const CoolantCircuits& cc) {
  nlohmann::ordered_json j{{"flowing", cc.flowing}, {"from_supply", cc.from_supply}, {"from_pump", cc.from_pump},
                           {"total_flow", cc.total_flow}};
  if (cc.from_supply) j["supply_pressure"] = cc.supply;  // Pa
  j["circuits"] = nlohmann::ordered_json::array();
  for (const CircuitHydraulics& c : cc.circuits) {
    nlohmann::ordered_json row{{"circuit", c.circuit},
                               {"kind", mold::to_string(c.kind)},
                               {"bores", c.bores},
                               {"turns", c.turns},
                               {"diameter", c.diameter},
                               {"length", c.length},
                               {"flow", c.flow},
                               {"velocity", c.drop.velocity},
                               {"reynolds", c.drop.reynolds},
                               {"regime", c.regime},
                               {"friction", c.drop.friction},
                               {"pressure_drop", {{"total", c.drop.total()}, {"pipe", c.drop.pipe}, {"turns", c.drop.turns}, {"ports", c.drop.ports}}},
                               {"film", c.film}};
    if (c.heat_known) {
      row["heat"] = c.heat, row["heat_share"] = c.heat_share;
      row["coolant_in"] = c.coolant_in, row["coolant_out"] = c.coolant_out, row["rise"] = c.rise;
    }
    j["circuits"].push_back(row);
  }
  j["checks"] = nlohmann::ordered_json::array();
  for (const ShopCheck& c : cc.checks)
    j["checks"].push_back({{"circuit", c.circuit}, {"what", c.what}, {"found", c.found}, {"limit", c.limit}, {"text", c.text()}});
  return j;
}

std::string coolant_circuits_json_text(const CoolantCircuits& cc) { return coolant_circuits_json(cc).dump(); }

}  // namespace mtcs::eval
