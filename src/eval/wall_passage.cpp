#include "mtcs/eval/wall_passage.h"

#include <cmath>
#include <numbers>

namespace mtcs::eval {

using std::numbers::pi;

WallPassage wall_passage(const mold::Bore& bore) {
  const double D = bore.diameter;
  switch (bore.kind) {
    case mold::CircuitKind::Drilled: return {pi * D * D / 4, D, 1};
    case mold::CircuitKind::Baffle:
      // A half-disc: area pi D^2 / 8, wetted by its arc and the blade, pi D / 2 + D.
      return {pi * D * D / 8, pi * D / (pi + 2), 1};
    case mold::CircuitKind::Bubbler: {
      const double d = bore.tube_outer, a = d / D;
      return {pi * (D * D - d * d) / 4, D - d, 0.9 - 0.15 * std::pow(a, 0.6)};
    }
  }
  return {pi * D * D / 4, D, 1};
}

PassageFlow passage_flow(const WallPassage& passage, double litres_per_minute, const WaterProperties& water) {
  const double velocity = litres_per_minute / 60e3 / (passage.area * 1e-6);  // m/s
  return {velocity, water.density * velocity * passage.hydraulic_diameter * 1e-3 / water.viscosity};
}

double passage_film(const WallPassage& passage, double litres_per_minute, double celsius) {
  const WaterProperties w = water_properties(celsius);
  const PassageFlow f = passage_flow(passage, litres_per_minute, w);
  const double film = passage.film_factor * tube_nusselt(f.reynolds, w.prandtl()) * w.conductivity /
                      (passage.hydraulic_diameter * 1e-3);  // W/(m^2 K)
  return film * 1e-6;
}

double wall_film(const mold::Bore& bore, double litres_per_minute, double celsius) {
  if (!is_blind(bore.kind)) return coolant_film(litres_per_minute, bore.diameter, celsius);
  return passage_film(wall_passage(bore), litres_per_minute, celsius);
}

}  // namespace mtcs::eval
