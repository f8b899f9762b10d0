#pragma once
// A cavity temperature as `mtcs thermal` prints it: the summary and heat balance as text or as one
// JSON object {tier, mean, std, max, hottest, surface, samples, heat_in, heat_to_bores, heat_to_faces,
// seconds}; temperatures at a user's points as CSV x,y,z,T (17 digits).

#include <ostream>
#include <vector>

#include "mtcs/eval/cavity_temperature.h"

namespace mtcs::eval {

void write_cavity_temperature_text(std::ostream& out, const CavityTemperature& r);
void write_cavity_temperature_json(std::ostream& out, const CavityTemperature& r);
void write_point_temperatures_csv(std::ostream& out, const std::vector<geometry::Vec3>& points,
                                  const std::vector<double>& temperatures);

}  // namespace mtcs::eval
