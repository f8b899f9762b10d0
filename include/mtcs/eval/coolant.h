#pragma once
// The coolant side of a bore: water properties and the film coefficient of fully developed
// flow in a smooth round tube (docs/mold-spec.md, "thermal.coolant"). Physics of the thermal
// model; it lives in eval for now and could move to the thermal module.

namespace mtcs::eval {

// Liquid water at saturation (about 1 atm below 100 degrees C), SI units.
struct WaterProperties {
  double density = 0;        // kg/m^3
  double specific_heat = 0;  // J/(kg K)
  double conductivity = 0;   // W/(m K)
  double viscosity = 0;      // Pa s (dynamic)
  double prandtl() const { return specific_heat * viscosity / conductivity; }
};

// Interpolated in Perry's Chemical Engineers' Handbook, 9th ed., Table 2-135 (saturated
// water, 273.16 to 380 K; NIST): linear in T, the viscosity log-linear. 0 to 106.85 degrees C;
// outside, the nearest end.
WaterProperties water_properties(double celsius);

// Petukhov's friction factor of a smooth tube, f = (0.790 ln Re - 1.64)^-2.
double petukhov_friction(double reynolds);
// Gnielinski (1976): Nu = (f/8)(Re - 1000) Pr / (1 + 12.7 sqrt(f/8) (Pr^(2/3) - 1)).
double gnielinski(double reynolds, double prandtl);
// Fully developed Nusselt number, constant wall temperature: 3.66 up to Re = 2300, Gnielinski
// from Re = 1e4, linear in Re in between (Gnielinski 2013, Int. J. Heat Mass Transfer 63:134,
// as in the VDI Heat Atlas G1), so the film grows continuously with the flow.
double tube_nusselt(double reynolds, double prandtl);
// The film coefficient (W/(mm^2 K), the thermal module's unit) of water at `celsius` flowing
// at `litres_per_minute` through a bore of `diameter_mm`.
double coolant_film(double litres_per_minute, double diameter_mm, double celsius);

}  // namespace mtcs::eval
