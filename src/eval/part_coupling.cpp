#include "mtcs/eval/part_coupling.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "mtcs/eval/cycle_time.h"

namespace mtcs::eval {

namespace {
using std::numbers::pi;
// Terms of the series: at Fo = 1e-4 the last kept term is below 1e-12 of the first.
constexpr int kTerms = 400;
}  // namespace

double slab_mean_fraction(double fourier) {
  if (!(fourier > 0)) return 1;
  double sum = 0;
  for (int k = 0; k < kTerms; ++k) {
    const double n = 2 * k + 1;
    sum += 8 / (n * n * pi * pi) * std::exp(-n * n * pi * pi * fourier);
  }
  return sum;
}

double slab_odd_buildup(double fourier) {
  if (!(fourier > 0)) return 0;
  double sum = 0;
  for (int m = 1; m <= kTerms; ++m) sum += -std::expm1(-4.0 * m * m * pi * pi * fourier) / (double(m) * m);
  // The tail, m > kTerms, as the integral from kTerms + 1/2 of (1 - exp(-a x^2)) / x^2:
  // (1 - exp(-a X^2)) / X + sqrt(pi a) erfc(sqrt(a) X).
  const double a = 4 * pi * pi * fourier, X = kTerms + 0.5;
  sum += -std::expm1(-a * X * X) / X + std::sqrt(pi * a) * std::erfc(std::sqrt(a) * X);
  return 6 / (pi * pi) * sum;
}

PartCoupling part_coupling(const mold::Polymer& polymer, double thickness, double in_mold, double cycle) {
  if (!(thickness > 0) || !(in_mold > 0) || !(in_mold <= cycle))
    throw std::invalid_argument("part coupling: needs a wall thickness > 0 and 0 < time in the mold <= cycle");
  const double s = thickness;
  const double rho_cp = polymer.density * polymer.specific_heat * 1e-9;  // J/(mm^3 K)
  const double k_p = polymer.diffusivity * rho_cp;                       // W/(mm K)
  const double fourier = polymer.diffusivity * in_mold / (s * s);
  PartCoupling c;
  c.temperature = polymer.melt_temperature;
  c.film = rho_cp * s * (1 - slab_mean_fraction(fourier)) / (2 * cycle);
  // The odd part's heat into the colder wall, less the half of h_p's that the even part, taken
  // at the walls' mean, gives to the other wall: 0 for short contacts (each wall then sees a
  // half-space of melt), floored there against the series' rounding.
  c.cross_film = std::max(0.0, (k_p * in_mold / s + rho_cp * s * slab_odd_buildup(fourier) / 12) / cycle - c.film / 2);
  return c;
}

CycleTimes nominal_cycle(const mold::MoldSpec& spec) {
  const mold::ThermalSpec& t = spec.thermal;
  const double s = spec.cavity ? spec.cavity->wall_thickness : mold::Cavity{}.wall_thickness;
  CycleTimes c;
  c.cooling = t.cycle.cooling ? *t.cycle.cooling : cooling_time(s, t.polymer, t.coolant_temperature);
  c.in_mold = t.cycle.fill + t.cycle.pack + c.cooling;
  c.cycle = c.in_mold + t.cycle.open;
  return c;
}

PartCoupling cavity_coupling(const mold::MoldSpec& spec) {
  const mold::ThermalSpec& t = spec.thermal;
  const double s = spec.cavity ? spec.cavity->wall_thickness : mold::Cavity{}.wall_thickness;
  const CycleTimes times = nominal_cycle(spec);
  PartCoupling c = part_coupling(t.polymer, s, times.in_mold, times.cycle);
  if (t.part_film) c.film = *t.part_film;
  if (t.part_temperature) c.temperature = *t.part_temperature;
  return c;
}

double consistent_cooling(const std::function<double(double)>& need, double start, double tolerance,
                          int max_evaluations, int* evaluations, std::optional<std::pair<double, double>> known) {
  // In logarithms (u = ln c, misfit ln need - u): the steep need of a mold near its eject
  // temperature is closer to a straight line there (the L-bracket's case: 4 evaluations to 1 %
  // instead of 7).
  // A known point counts as an evaluation; within tolerance, it is the answer.
  int count = known ? 1 : 0;
  double best = start, best_misfit = std::numeric_limits<double>::infinity();
  if (known) {
    best = known->first, best_misfit = std::abs(known->second - known->first) / known->first;
    if (best_misfit <= tolerance) {
      if (evaluations) *evaluations = count;
      return best;
    }
  }
  bool done = false;
  const auto misfit = [&](double u, double c) {  // c = e^u, exactly `start` at first
    const double n = need(c);
    ++count;
    const double relative = std::abs(n - c) / c;
    if (relative < best_misfit) best = c, best_misfit = relative;
    done = relative <= tolerance || count >= max_evaluations;
    return std::log(n) - u;
  };
  double a = std::log(start), fa = misfit(a, start);
  if (!done) {
    double b, fb;
    if (known && known->first > 0 && known->second > 0 &&
        (std::log(known->second / known->first) > 0) != (fa > 0)) {
      b = a, fb = fa;
      a = std::log(known->first), fa = std::log(known->second) - a;
    } else {
      b = a + fa, fb = misfit(b, std::exp(b));  // at need(start): the other side, need decreasing
    }
    while (!done && fa * fb < 0) {
      const double c = b - fb * (b - a) / (fb - fa), fc = misfit(c, std::exp(c));
      if (fc * fb < 0) a = b, fa = fb;
      else fa /= 2;  // Illinois: the end kept again weighs half, or regula falsi creeps
      b = c, fb = fc;
    }
  }
  if (evaluations) *evaluations = count;
  return best;
}

double follow_cycle(std::vector<double>& temperature, const mold::MoldSpec& spec, std::size_t deciding,
                    std::span<const double> thickness) {
  const mold::ThermalSpec& t = spec.thermal;
  const double nominal = nominal_cycle(spec).cooling;
  deciding = std::min(deciding, temperature.size());
  if (t.cavity_condition != mold::CavityCondition::Coupled || t.cycle.cooling || t.part_film || deciding == 0)
    return nominal;
  const std::size_t slowest = slowest_place(temperature, thickness, t.polymer, deciding);
  const double s = !thickness.empty() ? thickness[slowest]
                   : spec.cavity     ? spec.cavity->wall_thickness
                                     : mold::Cavity{}.wall_thickness;
  const CycleTimes times = nominal_cycle(spec);
  const double start_film = part_coupling(t.polymer, s, times.in_mold, times.cycle).film;
  const PartCoupling start = cavity_coupling(spec);
  const double coolant = t.coolant_temperature, span = start.temperature - coolant;
  if (!(span > 0) || !std::all_of(temperature.begin(), temperature.end(), [](double v) { return std::isfinite(v); }))
    return nominal;
  // The share of a sample at the film x h_0 (below the coolant: left as solved).
  const auto share = [](double r, double x) { return r <= 0 ? r : x * r / (x * r + 1 - r); };
  const double hottest = std::min(temperature[slowest] - coolant, span) / span;
  const auto film_ratio = [&](double cooling) {
    const double in_mold = t.cycle.fill + t.cycle.pack + cooling;
    return part_coupling(t.polymer, s, in_mold, in_mold + t.cycle.open).film / start_film;
  };
  // At the nominal film the part cannot be ejected: the answer stands there.
  if (coolant + span * hottest >= t.polymer.eject_temperature) return nominal;
  const double cooling = consistent_cooling(
      [&](double c) { return cooling_time(s, t.polymer, coolant + span * share(hottest, film_ratio(c))); }, nominal, 1e-3, 60);
  const double x = film_ratio(cooling);
  if (x != 1)
    for (double& v : temperature) v = coolant + span * share(std::min(v - coolant, span) / span, x);
  return cooling;
}

}  // namespace mtcs::eval
