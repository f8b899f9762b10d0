// The coolant film and the cycle-time proxy against independent numbers: water's Prandtl number
// from a second table, Gnielinski's Nusselt number worked by hand and against Dittus-Boelter,
// the plate cooling time against the full Fourier series of the slab.

#include <catch2/catch.hpp>
#include <cmath>

#include "mtcs/eval/coolant.h"
#include "mtcs/eval/cycle_time.h"

using namespace mtcs;

namespace {
constexpr double kPi = 3.14159265358979323846;
}

TEST_CASE("coolant: water's Prandtl number matches a second table", "[eval][coolant]") {
  // Cengel, Heat and Mass Transfer, Table A-9 (saturated water): Pr at 20, 40, 60, 80 C.
  const double table[][2] = {{20, 7.01}, {40, 4.32}, {60, 2.99}, {80, 2.22}};
  for (const auto& [celsius, pr] : table) CHECK(eval::water_properties(celsius).prandtl() == Approx(pr).epsilon(0.015));
  // Densities from the same table: 998.0 kg/m^3 at 20 C, 992.1 at 40 C.
  CHECK(eval::water_properties(20).density == Approx(998.0).epsilon(0.002));
  CHECK(eval::water_properties(40).density == Approx(992.1).epsilon(0.002));
  // Perry's table itself at a node (300 K): 853.84 uPa s, 610.28 mW/(m K).
  CHECK(eval::water_properties(26.85).viscosity == Approx(853.84e-6).epsilon(1e-9));
  CHECK(eval::water_properties(26.85).conductivity == Approx(0.61028).epsilon(1e-9));
}

TEST_CASE("coolant: Gnielinski's Nusselt number at Re 1e4 and 1e5, Pr 4.3 and 7", "[eval][coolant]") {
  // Worked by hand from Nu = (f/8)(Re-1000)Pr / (1 + 12.7 sqrt(f/8)(Pr^(2/3)-1)),
  // f = (0.790 ln Re - 1.64)^-2: e.g. Re 1e4: f = 5.6362^-2 = 0.031480; Pr 4.3: Pr^(2/3) = 2.6443.
  CHECK(eval::petukhov_friction(1e4) == Approx(0.031480).epsilon(1e-4));
  CHECK(eval::gnielinski(1e4, 4.3) == Approx(65.925).epsilon(1e-4));
  CHECK(eval::gnielinski(1e4, 7.0) == Approx(79.493).epsilon(1e-4));
  CHECK(eval::gnielinski(1e5, 4.3) == Approx(481.03).epsilon(1e-4));
  CHECK(eval::gnielinski(1e5, 7.0) == Approx(599.07).epsilon(1e-4));
  // Dittus-Boelter, Nu = 0.023 Re^0.8 Pr^0.4 (an independent fit), agrees within its own
  // +-25 % (Incropera 8.5): closely at Re 1e4, 15-20 % lower at 1e5.
  for (const double re : {1e4, 1e5})
    for (const double pr : {4.3, 7.0}) {
      const double db = 0.023 * std::pow(re, 0.8) * std::pow(pr, 0.4);
      CHECK(std::abs(eval::gnielinski(re, pr) / db - 1) < 0.25);
    }
}

TEST_CASE("coolant: laminar, transitional and turbulent join continuously", "[eval][coolant]") {
  CHECK(eval::tube_nusselt(500, 5) == 3.66);
  CHECK(eval::tube_nusselt(2300, 5) == 3.66);
  CHECK(eval::tube_nusselt(2300.001, 5) == Approx(3.66).epsilon(1e-5));
  CHECK(eval::tube_nusselt(1e4, 5) == eval::gnielinski(1e4, 5));
  CHECK(eval::tube_nusselt(9999.999, 5) == Approx(eval::gnielinski(1e4, 5)).epsilon(1e-5));
  // Halfway in Re: halfway in Nu.
  CHECK(eval::tube_nusselt(6150, 5) == Approx((3.66 + eval::gnielinski(1e4, 5)) / 2).epsilon(1e-12));
  double last = 0;
  for (double re = 100; re < 1e6; re *= 1.1) {
    const double nu = eval::tube_nusselt(re, 5);
    CHECK(nu >= last);
    last = nu;
  }
}

TEST_CASE("coolant: the film of 8 l/min through an 8 mm bore at 40 C", "[eval][coolant]") {
  // By hand from Perry's table at 313.15 K: rho 992.08, c_p 4179.9, k 0.63035, mu 654.50e-6,
  // Pr 4.3400; v = 2.6526 m/s, Re = 32166, Nu = 183.91, h = Nu k / D = 14491 W/(m^2 K).
  CHECK(eval::coolant_film(8, 8, 40) == Approx(14491.4e-6).epsilon(1e-4));
  // A trickle is laminar: Nu 3.66, h = 3.66 k / D.
  CHECK(eval::coolant_film(0.01, 8, 40) == Approx(3.66 * 0.63035 / 0.008 * 1e-6).epsilon(1e-4));
}

TEST_CASE("cycle time: the plate formula against the Fourier series of the slab", "[eval][cycle_time]") {
  // Slab of thickness s between walls at T_w, initially T_m: centre-line temperature
  // (T_c - T_w)/(T_m - T_w) = (4/pi) sum_n (-1)^n/(2n+1) exp(-(2n+1)^2 pi^2 alpha t / s^2)
  // (Carslaw & Jaeger 3.3). At the cooling time it must be the eject temperature.
  mold::Polymer polymer;  // 230 / 90 C, 0.095 mm^2/s
  for (const double s : {1.0, 2.5, 4.0}) {
    for (const double wall : {20.0, 40.0, 60.0, 85.0}) {
      const double t = eval::cooling_time(s, polymer, wall);
      const double fo = polymer.diffusivity * t / (s * s);
      double theta = 0;
      for (int n = 0; n < 50; ++n)
        theta += 4 / kPi * (n % 2 ? -1 : 1) / (2 * n + 1) * std::exp(-(2 * n + 1) * (2 * n + 1) * kPi * kPi * fo);
      const double centre = wall + theta * (polymer.melt_temperature - wall);
      CHECK(centre == Approx(polymer.eject_temperature).epsilon(1e-5));
    }
  }
  // A worked number: s = 2 mm, alpha 0.1 mm^2/s, 240 -> 90 C, wall 60 C:
  // 4/(pi^2 0.1) ln((4/pi)(180/30)) = 4.0528 * 2.0333 = 8.2407 s.
  const mold::Polymer abs{240, 90, 0.1, 1050, 2000};
  CHECK(eval::cooling_time(2, abs, 60) == Approx(8.2407).epsilon(1e-4));
}

TEST_CASE("cycle time: finite and increasing up to and past the eject temperature", "[eval][cycle_time]") {
  const mold::Polymer polymer;
  double last = 0;
  for (double wall = 0; wall < 150; wall += 0.25) {
    const double t = eval::cooling_time(2.5, polymer, wall);
    CHECK(std::isfinite(t));
    CHECK(t > last);
    last = t;
  }
  // Continuous at the knee, 1 K below ejection.
  CHECK(eval::cooling_time(2.5, polymer, 89 + 1e-9) == Approx(eval::cooling_time(2.5, polymer, 89 - 1e-9)).epsilon(1e-8));
}

TEST_CASE("cycle time: the default heat flux from the part", "[eval][cycle_time]") {
  // Defaults: rho c_p = 2.1e6 J/(m^3 K), s/2 = 1.25 mm, 140 K: 367 500 J/m^2 per cycle and side,
  // over t_c(40 C) = 6.25/(pi^2 0.095) ln((4/pi) 190/50) = 10.509 s: 34 969 W/m^2.
  mold::MoldSpec spec;
  CHECK(eval::default_heat_flux(spec) == Approx(34969.4e-6).epsilon(1e-4));
  spec.cavity = mold::Cavity{};
  spec.cavity->wall_thickness = 5;  // twice the heat over four times the cooling time
  CHECK(eval::default_heat_flux(spec) == Approx(34969.4e-6 / 2).epsilon(1e-4));
}
