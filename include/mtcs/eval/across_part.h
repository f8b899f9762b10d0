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

// The points across join `samples` after them, unweighted (the samples' summary stays theirs),
// each with its sample's wall thickness and the opposite normal: what a solve for the
// difference takes.
void append_across(thermal::Samples& samples, const std::vector<std::optional<geometry::Vec3>>& across);

// The core/cavity difference: over the samples whose wall has the part's other face straight
// across it, |T(sample) - T(across)|.
struct WallDifference {
  std::size_t pairs = 0;
  double paired_area = 0;      // mm^2, of those samples
  double mean = 0, max = 0;    // K, area-weighted mean and max
  geometry::Vec3 where = geometry::Vec3::Zero();  // the sample of the max
};

// `at_samples` at the samples; `at_across` at the points across, in the samples' order, one
// per sample that has one (`across` from across_part).
WallDifference wall_difference(const std::vector<double>& at_samples, const std::vector<double>& at_across,
                               const thermal::Samples& samples, const std::vector<std::optional<geometry::Vec3>>& across);

}  // namespace mtcs::eval
