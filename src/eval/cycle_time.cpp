#include "mtcs/eval/cycle_time.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace mtcs::eval {

namespace {
using std::numbers::pi;
constexpr double kTangentBelowEject = 1.0;  // K
}  // namespace

double cooling_time(double wall_thickness, const mold::Polymer& polymer, double wall_temperature) {
  const double scale = wall_thickness * wall_thickness / (pi * pi * polymer.diffusivity);
  const double melt = polymer.melt_temperature, eject = polymer.eject_temperature;
  auto exact = [&](double t) { return scale * std::log(4 / pi * (melt - t) / (eject - t)); };
  const double knee = eject - kTangentBelowEject;
  if (wall_temperature <= knee) return exact(wall_temperature);
  const double slope = scale * (1 / (eject - knee) - 1 / (melt - knee));
  return exact(knee) + slope * (wall_temperature - knee);
}

std::size_t slowest_place(std::span<const double> temperature, std::span<const double> thickness,
                          const mold::Polymer& polymer, std::size_t deciding) {
  deciding = std::min(deciding, temperature.size());
  std::size_t slowest = 0;
  if (thickness.empty()) {
    for (std::size_t i = 1; i < deciding; ++i)
      if (temperature[i] > temperature[slowest]) slowest = i;
    return slowest;
  }
  double longest = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < deciding; ++i)
    if (const double t = cooling_time(thickness[i], polymer, temperature[i]); t > longest) longest = t, slowest = i;
  return slowest;
}

double default_heat_flux(const mold::MoldSpec& spec) {
  const mold::Polymer& p = spec.thermal.polymer;
  const double s = spec.cavity ? spec.cavity->wall_thickness : mold::Cavity{}.wall_thickness;  // mm
  // J/m^2 per cycle on each side, then W/mm^2.
  const double heat = p.density * p.specific_heat * (s / 2 * 1e-3) * (p.melt_temperature - p.eject_temperature);
  return heat / cooling_time(s, p, spec.thermal.coolant_temperature) * 1e-6;
}

}  // namespace mtcs::eval
