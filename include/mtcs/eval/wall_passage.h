#pragma once
// Where the coolant sweeps a bore's wall (docs/coolant-circuits.md, "Baffles and bubblers"): a
// drilled bore's whole round; a baffle's half, the blade splitting the bore into two half-discs
// (the flow down one, back up the other); a bubbler's annulus between the bore and its tube (the
// flow up the tube, back down the annulus). Each passage's film and friction follow the round
// tube's correlations at its hydraulic diameter 4A/P (Incropera 6th ed. 8.7, turbulent flow in
// non-circular ducts), the annulus's film times Gnielinski's factor for an annulus heated at its
// outer wall, 0.9 - 0.15 (d_o/D)^0.6 (VDI Heat Atlas G2, Gnielinski 2009).

#include "mtcs/eval/coolant.h"
#include "mtcs/mold/layout.h"

namespace mtcs::eval {

struct WallPassage {
  double area = 0;                // mm^2, the flow's cross-section
  double hydraulic_diameter = 0;  // mm, 4 area / wetted perimeter
  double film_factor = 1;         // on the round tube's Nusselt number at that diameter
};

// The passage along `bore`'s wall (its kind, diameter, and a bubbler's tube).
WallPassage wall_passage(const mold::Bore& bore);

// Velocity (m/s) and Reynolds number of `litres_per_minute` of `water` through the passage.
struct PassageFlow {
  double velocity = 0, reynolds = 0;
};
PassageFlow passage_flow(const WallPassage& passage, double litres_per_minute, const WaterProperties& water);

// The film coefficient (W/(mm^2 K), the thermal module's unit) on the bore's wall of water at
// `celsius` flowing at `litres_per_minute` through the passage.
double passage_film(const WallPassage& passage, double litres_per_minute, double celsius);
// The film on `bore`'s wall: coolant_film for a drilled bore, passage_film of its passage otherwise.
double wall_film(const mold::Bore& bore, double litres_per_minute, double celsius);

}  // namespace mtcs::eval
