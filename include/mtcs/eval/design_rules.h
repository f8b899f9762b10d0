#pragma once
// The rules of thumb a mold designer checks a cooling layout against (issue 42 item 6), per bore,
// in bore diameters D: the depth of its axis under the cavity (1.5-2.5 D: nearer, the steel
// over it runs cold in a stripe and weakens; farther, it cools little), the pitch to the nearest
// bore it does not meet at a junction (3-5 D: closer, the pair competes for the same heat;
// farther, the steel between runs warm), the drilled depth per diameter (against
// drilling.max_depth_ratio, which the drilling stage enforces). Reported, not enforced: the
// temperature objectives judge the layout itself.

#include <limits>
#include <string>
#include <vector>

#include "mtcs/mold/layout.h"
#include "mtcs/mold/scene.h"

namespace mtcs::eval {

struct DesignRange {
  double low = 0, high = 0;  // in diameters
};
inline constexpr DesignRange kDepthRange{1.5, 2.5}, kPitchRange{3, 5};

struct BoreRules {
  std::string bore;  // c0.b2
  double diameter = 0;                                         // mm
  // mm, axis to the cavity: the steel between the drilled hole (dead ends and drill point
  // included) and the part, plus the radius; exact where the hole's side faces the part, the
  // radius too deep where its end does (none: inf).
  double depth = std::numeric_limits<double>::infinity();
  double pitch = std::numeric_limits<double>::infinity();      // mm, axis to axis (no other bore: inf)
  std::string pitch_to;                                        // the nearest bore
  double drilled_ratio = 0;                                    // drilled length / diameter
  double depth_d() const { return depth / diameter; }
  double pitch_d() const { return pitch / diameter; }
};

struct DesignRules {
  std::vector<BoreRules> bores;  // the layout's order
  double max_depth_ratio = 0;    // drilling.max_depth_ratio
  // "near", "far" or "" (within the range) for a value in diameters.
  static std::string verdict(double in_diameters, DesignRange range);
};

DesignRules design_rules(const mold::Scene& scene, const mold::Layout& layout);
// A table of one row per bore, each value in diameters with its verdict.
std::string design_rules_text(const DesignRules& rules);
// The same as one JSON object as text: {depth_range, pitch_range, max_depth_ratio, bores [{bore,
// diameter, depth, depth_d, depth_verdict, pitch, pitch_d, pitch_to, pitch_verdict, drilled_ratio}]}
// (mm; a missing distance as null).
std::string design_rules_json_text(const DesignRules& rules);

}  // namespace mtcs::eval
