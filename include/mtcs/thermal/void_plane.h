#pragma once
// The cavity void for the line-sink tiers, which know only the block's planar faces: a thin box
// cavity (a plate) cut off from the steel beyond it. Its most heated face becomes a block face:
// the block is cut there, the cut is adiabatic (the void, and the steel beyond it fed only
// around the cavity's rim), and that face takes the whole cavity's heat, as a patch takes it on
// the reference block. Without it the line sinks let half the heat of the plate's lower face
// leave upward through the "void" into the steel above, which spreads it: on molds/plate.yaml
// they rank layouts against T3 with Kendall tau 0.84 over the heated faces, 0.95 with the cut
// (experiments/thermal/void_plane.md). T3 models the void itself and needs none of this.
//
// Samples off the cut block (the cavity's side faces) see the mirror image of the steel below
// the cut: the adiabatic face reflects every source with the same sign.

#include "mtcs/thermal/model.h"

namespace mtcs::thermal {

// The setting with the block cut at the box cavity's most heated face (above). Unchanged when
// there is no box cavity or no heat enters through one of its faces.
Setting cut_at_cavity_void(const Setting& setting);

}  // namespace mtcs::thermal
