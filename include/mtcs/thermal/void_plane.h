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
// the cut: the adiabatic face reflects every source with the same sign. Channels beyond the cut
// (bores in the frame beside the cavity, or over it) are folded back the same way: mirrored
// across the cut plane, which keeps their effect on the rim but overstates that of a bore over
// the cavity (in T3 the void hides it).

#include <span>
#include <vector>

#include "mtcs/thermal/model.h"

namespace mtcs::thermal {

struct CavityCut {
  Setting setting;         // the cut block, or the setting unchanged (axis < 0)
  int axis = -1;           // the cut plane's normal axis; -1: no cut
  double plane = 0;        // its coordinate
  bool keep_below = true;  // the block kept lies below the plane (a cavity's lower face)
  // The channels with their parts beyond the plane mirrored across it (one crossing the plane
  // is split there).
  std::vector<Channel> fold(std::span<const Channel> channels) const;
  // Each channel's heat from that of its folded parts (`folded_heat` in fold's order): a split
  // channel's two parts summed.
  std::vector<double> unfold_heat(std::span<const Channel> channels, std::span<const double> folded_heat) const;

 private:
  bool splits(const Channel& channel) const;  // crosses the plane: fold makes two parts of it
  double beyond(const Vec3& p) const;         // signed height past the plane (> 0: the side cut off)
};

// The setting with the block cut at the box cavity's most heated face (above). No cut when
// there is no box cavity or no heat enters through one of its faces.
CavityCut cut_at_cavity_void(const Setting& setting);

}  // namespace mtcs::thermal
