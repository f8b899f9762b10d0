#pragma once
// The coolant circuits as `mtcs thermal` and `mtcs evaluate` print them: a table of one row per
// circuit (flow l/min, velocity m/s, Reynolds number, drop bar, heat W, rise K, film W/(m^2 K))
// and the shop checks it breaks; or a JSON object {flowing, from_supply, from_pump, total_flow,
// supply_pressure (Pa, when a pressure drives the flows), circuits,
// checks} in SI units (the drop in Pa). Empty text when no flow is given. Inside eval: the
// JSON library stays private to the module.

#include <nlohmann/json.hpp>
#include <string>

#include "mtcs/eval/circuit_hydraulics.h"

namespace mtcs::eval {

std::string coolant_circuits_text(const CoolantCircuits& circuits);
nlohmann::ordered_json coolant_circuits_json(const CoolantCircuits& circuits);

}  // namespace mtcs::eval
