#pragma once
// The part's two sides: the faces the core half of the mold forms and those the cavity half
// forms (cavity.parting). A spread over the whole cavity mixes each side's in-plane spread with
// the offset between the halves (temperature_difference measures that); per side it does not.

#include <cmath>
#include <vector>

#include "mtcs/mold/scene.h"
#include "mtcs/thermal/model.h"

namespace mtcs::eval {

enum class PartSide : unsigned char { Core, Cavity };

// Per sample: the half of the mold whose steel lies behind it (a hair along its normal), for a
// straight pull along the parting's axis. Steel on a half's side of the parting plane is that
// half's, unless it reaches into the part from the other half: seen along the axis, the part is
// behind it (the other half could not be pulled out with it) and nothing of the part lies
// between it and the plane (its own half can). So a cup's core, which stands below the parting
// plane inside the cup, is the core's. A helical face (a herringbone gear's flank) has no straight
// pull: some of its samples fall to the wrong half. Empty without cavity.parting.
std::vector<PartSide> part_sides(const mold::Scene& scene, const thermal::Samples& samples);

// Area-weighted over one side's samples.
struct SideSummary {
  double area = 0;             // mm^2
  double mean = 0, std = 0;    // degrees C, K
  double max = 0;              // degrees C
};
struct SideSummaries {
  SideSummary core, cavity;
  double larger_std() const { return core.std > cavity.std || std::isnan(core.std) ? core.std : cavity.std; }  // K, NaN kept
};
SideSummaries side_summaries(const std::vector<double>& temperature, const thermal::Samples& samples,
                             const std::vector<PartSide>& sides);

}  // namespace mtcs::eval
