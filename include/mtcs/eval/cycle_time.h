#pragma once
// The cycle-time proxy (shared/notes/mtcs_literature.md 4.7) and the heat flux it implies.
// Physics of the thermal model; it lives in eval for now and could move to the thermal module.

#include <cstddef>
#include <span>

#include "mtcs/mold/mold_spec.h"

namespace mtcs::eval {

// Cooling time (s) of a plate of thickness `wall_thickness` (mm) between mold walls at
// `wall_temperature` until its centre line reaches the eject temperature, first term of the
// Fourier series: t_c = s^2/(pi^2 alpha) ln((4/pi)(T_melt - T_wall)/(T_eject - T_wall)).
// Within 1 K of the eject temperature and above, continued along its tangent: finite and
// increasing, so an optimiser never sees infinity.
double cooling_time(double wall_thickness, const mold::Polymer& polymer, double wall_temperature);

// The place that cools last, whose cooling time sets the cycle: of the first `deciding` values
// of `temperature`, the one of the longest cooling_time at `thickness` (per place, mm), or the
// hottest when `thickness` is empty (one wall for all).
std::size_t slowest_place(std::span<const double> temperature, std::span<const double> thickness,
                          const mold::Polymer& polymer, std::size_t deciding);

// The default cycle-averaged heat flux (W/mm^2) into the steel through the cavity surface: the
// heat each half of the part gives up per cycle, rho c_p (s/2) (T_melt - T_eject) per unit
// area, over the cooling time with the wall at the coolant temperature (no dwell: an upper
// estimate). For the defaults (ABS-like, s = 2.5 mm, coolant 40 degrees C): 35 kW/m^2.
double default_heat_flux(const mold::MoldSpec& spec);

}  // namespace mtcs::eval
