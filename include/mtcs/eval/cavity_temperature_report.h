#pragma once
// A cavity temperature as `mtcs thermal` prints it: the summary and heat balance as text or as one
// JSON object {tier, mean, std, max, hottest, above_melt, surface, samples, heat_in, heat_to_bores, heat_to_faces,
// seconds}; the surface field (.vtp, .ply); temperatures at a user's points as CSV x,y,z,T (17 digits).

#include <ostream>
#include <string>
#include <vector>

#include "mtcs/eval/cavity_temperature.h"

namespace mtcs::eval {

void write_cavity_temperature_text(std::ostream& out, const CavityTemperature& r);
// Whether a fixed flux put the wall above the melt that heats it (no mold can run there), and the
// warning that says so ("" when not); the text and JSON (`above_melt`) carry it too.
bool above_melt(const CavityTemperature& r);
std::string above_melt_text(const CavityTemperature& r);
// The above-melt warning (below) goes to `warnings` too: stdout is for machines.
void write_cavity_temperature_json(std::ostream& out, const CavityTemperature& r, std::ostream& warnings);
// The field on the cavity surface: VTK PolyData, or PLY coloured from the coldest vertex (or three
// std below the mean, if that is warmer: one cold spot should not wash out the rest) to the
// hottest sample.
void write_cavity_temperature_field(std::ostream& out, const CavityTemperature& r, bool vtp);
void write_point_temperatures_csv(std::ostream& out, const std::vector<geometry::Vec3>& points,
                                  const std::vector<double>& temperatures);

}  // namespace mtcs::eval
