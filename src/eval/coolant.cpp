#include "mtcs/eval/coolant.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace mtcs::eval {

namespace {

using std::numbers::pi;
constexpr double kMolarMass = 18.015e-3;  // kg/mol

// Perry's 9th ed. Table 2-135, saturated liquid: T (K), density (mol/dm^3), c_p (kJ/(mol K)),
// thermal conductivity (mW/(m K)), viscosity (uPa s).
struct Row {
  double kelvin, molar_density, molar_cp, conductivity_mw, viscosity_upa;
};
constexpr std::array<Row, 12> kWater{{
    {273.16, 55.497, 0.076023, 561.04, 1791.2},
    {280, 55.501, 0.075688, 574.04, 1433.7},
    {290, 55.440, 0.075429, 592.73, 1084.0},
    {300, 55.315, 0.075320, 610.28, 853.84},
    {310, 55.139, 0.075294, 626.05, 693.54},
    {320, 54.919, 0.075317, 639.71, 577.02},
    {330, 54.662, 0.075373, 651.18, 489.49},
    {340, 54.371, 0.075456, 660.55, 421.97},
    {350, 54.049, 0.075567, 668.00, 368.77},
    {360, 53.698, 0.075708, 673.76, 326.10},
    {370, 53.321, 0.075883, 678.02, 291.36},
    {380, 52.918, 0.076098, 681.00, 262.69},
}};

}  // namespace

WaterProperties water_properties(double celsius) {
  const double t = std::clamp(celsius + 273.15, kWater.front().kelvin, kWater.back().kelvin);
  std::size_t i = 0;
  while (i + 2 < kWater.size() && t > kWater[i + 1].kelvin) ++i;
  const Row& a = kWater[i];
  const Row& b = kWater[i + 1];
  const double s = (t - a.kelvin) / (b.kelvin - a.kelvin);
  auto lerp = [s](double x, double y) { return x + s * (y - x); };
  WaterProperties w;
  w.density = lerp(a.molar_density, b.molar_density) * 1e3 * kMolarMass;
  w.specific_heat = lerp(a.molar_cp, b.molar_cp) * 1e3 / kMolarMass;
  w.conductivity = lerp(a.conductivity_mw, b.conductivity_mw) * 1e-3;
  w.viscosity = std::exp(lerp(std::log(a.viscosity_upa), std::log(b.viscosity_upa))) * 1e-6;
  return w;
}

double petukhov_friction(double reynolds) {
  const double d = 0.790 * std::log(reynolds) - 1.64;
  return 1 / (d * d);
}

double gnielinski(double reynolds, double prandtl) {
  const double f8 = petukhov_friction(reynolds) / 8;
  return f8 * (reynolds - 1000) * prandtl / (1 + 12.7 * std::sqrt(f8) * (std::pow(prandtl, 2.0 / 3) - 1));
}

double tube_nusselt(double reynolds, double prandtl) {
  constexpr double kLaminar = 3.66, kLow = 2300, kHigh = 1e4;
  if (reynolds <= kLow) return kLaminar;
  if (reynolds >= kHigh) return gnielinski(reynolds, prandtl);
  const double gamma = (reynolds - kLow) / (kHigh - kLow);
  return (1 - gamma) * kLaminar + gamma * gnielinski(kHigh, prandtl);
}

double coolant_film(double litres_per_minute, double diameter_mm, double celsius) {
  const WaterProperties w = water_properties(celsius);
  const double d = diameter_mm * 1e-3;                                // m
  const double speed = litres_per_minute / 60e3 / (pi * d * d / 4);  // m/s
  const double reynolds = w.density * speed * d / w.viscosity;
  const double film = tube_nusselt(reynolds, w.prandtl()) * w.conductivity / d;  // W/(m^2 K)
  return film * 1e-6;
}

}  // namespace mtcs::eval
