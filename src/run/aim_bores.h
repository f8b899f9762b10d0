#pragma once
// AM-guided drilling directions (drilling.access_map): a bore whose direction lies in a blocked
// cell of the accessibility map at its entry is turned about its entry point to a free
// direction of that map within the entry angle limit, drawn at random among those closest to its
// direction (up to two cell heights farther than the nearest). Its waypoints keep their distances
// from the entry, and the rest of the circuit on either side moves with them, so the other
// bores keep their directions (ports are put back on their faces by the caller's repair).
// Directions that would bring an interior waypoint within bore_surface + radius of the block's
// faces are not drawn.

#include "mtcs/eval/drill_access.h"
#include "mtcs/mold/genome.h"
#include "mtcs/mold/scene.h"
#include "mtcs/opt/rng.h"

namespace mtcs::run {

// Aims the circuit's blocked bores in order (each decoded after the previous one moved).
// Returns how many were turned.
int aim_bores(const eval::DrillAccess& access, const mold::Scene& scene, mold::Circuit& circuit, opt::Rng& rng);

}  // namespace mtcs::run
