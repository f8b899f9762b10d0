#pragma once
// The part's other face straight across its wall: where a shell's core side faces its cavity
// side. For the core/cavity temperature difference (the warpage driver a cooling analysis
// reports as "temperature difference").

#include <optional>
#include <vector>

#include "mtcs/mold/scene.h"
#include "mtcs/thermal/model.h"

namespace mtcs::eval {

// Per sample with a normal: the point of the cavity surface straight across the part from it
// (along -normal), when that ray leaves the part through a face turned the other way (normals
// within 37 degrees of opposite) within `reach` mm; none where it leaves through a rim or an
// edge, goes farther (a thick section), or the cavity is a patch.
std::vector<std::optional<geometry::Vec3>> across_part(const mold::Scene& scene, const thermal::Samples& samples,
                                                       double reach);

}  // namespace mtcs::eval
