#pragma once
// Genome -> drilling plan (shared/notes/mtcs_literature.md 7.2).

#include "mtcs/mold/genome.h"
#include "mtcs/mold/layout.h"
#include "mtcs/mold/scene.h"

namespace mtcs::mold {

// With drilling.axis_parallel, a step between two waypoints that differ in more than one
// coordinate is routed along the axes (longest leg first), so every hole is axis-parallel and
// the inlet and outlet stay where they are; along an axis no allowed face can be drilled from
// (z, when only the side faces are allowed), the circuit keeps its inlet's coordinate: a silent
// repair of the optimiser's genomes only, since a user's layout that needs it is refused by
// mold::read_layout (beyond 0.01 mm) and reports what it snapped. Each flow segment is drilled from whichever end
// gives the shorter hole through an allowed face (any face when neither is allowed; the
// violation is reported). Holes extend past their far waypoint by the drill point,
// 0.5 D cot(tip/2), plus drilling.min_overlap, unless that waypoint is the inlet or outlet.
// A baffle's or bubbler's circuit is one blind hole: drilled from the face of
// drilling.baffles.faces nearest its entry waypoint, along that face's inward normal, to the depth
// of its tip waypoint (at least a diameter; the drill point inside the block), the flow from the
// entry to the tip and back, both ports at the entry.
Layout decode(const Scene& scene, const Genome& genome);

// A blind circuit's drilled axis: its entry on the face, its tip below the entry, the face.
struct BlindAxis {
  geometry::Vec3 entry, tip;
  Face face = Face::PosZ;
};
BlindAxis blind_axis(const Scene& scene, const Circuit& circuit);

// The waypoints actually drilled, after axis-parallel routing, dropping repeated points and
// merging straight runs.
std::vector<geometry::Vec3> routed_waypoints(const Scene& scene, const Circuit& circuit);

// The genome of what decode drills: every circuit's routed waypoints (circuits that drill
// nothing dropped). It decodes to the same plan, and a layout file written from it is read
// back as written (mold::read_layout reports no change): what optimisers save.
Genome drilled_genome(const Scene& scene, const Genome& genome);

}  // namespace mtcs::mold
