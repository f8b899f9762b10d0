#pragma once
// Exact, upper-bounded distance between two SOLID cylinders: Biermann, Joliet, Michelitsch,
// "Fast Distance Computation between Cylinders for the Design of Mold Temperature Control
// Systems", Algorithm 1, with the deviations listed in docs/distance-kernel.md.
//
// Guarantee: when the true distance is below `upper_bound`, `distance` is exact to the
// tolerance and `bounded` is false. Otherwise either the exact distance is returned, or
// `bounded` is true and `distance` (>= upper_bound) is a proven lower bound; witnesses are then
// unspecified. Intersecting or nested cylinders give distance 0, feature Intersecting. The query
// does not allocate.

#include <limits>
#include <string_view>

#include "mtcs/geometry/primitives.h"

namespace mtcs::geometry {

enum class Feature { ShellShell, ShellRim, RimDisk, RimRim, DiskDisk, Intersecting, Bounded };

std::string_view to_string(Feature f);

struct DistanceRequest {
  double upper_bound = std::numeric_limits<double>::infinity();
  // Target error of the numerical (circle) parts, relative to max(1, S).
  double tolerance = 1e-12;
  // Ablations of the paper's speed-ups, for benchmarks; results stay exact without them.
  bool pretests = true;       // axis-segment pretest with early return and upper-bound exit
  bool sorted_bounds = true;  // rims visited in order of their lower bounds, with early exit
  // Re-run pairs within 1e-10 * S of contact in 113-bit precision, so that touching and
  // barely separated pairs get the right verdict.
  bool exact_verdict = true;
};

struct DistanceResult {
  double distance = 0;
  Vec3 witness_a = Vec3::Zero();  // point of the first cylinder
  Vec3 witness_b = Vec3::Zero();  // point of the second cylinder
  Feature feature = Feature::Intersecting;
  bool bounded = false;         // only "distance >= upper_bound" was proved
  bool extended_precision = false;  // the verdict came from the 113-bit re-run

  bool intersecting() const { return feature == Feature::Intersecting; }
};

DistanceResult distance(const Cylinder& a, const Cylinder& b, const DistanceRequest& request = {});

// Baseline for benchmarks and a second method for tests: computes all seventeen sub-distances of
// the surfaces (shell-shell, 4 circle-shell, 8 circle-disk, 4 circle-circle) with no pretest or
// ordering, takes the minimum, and decides intersection and containment separately.
DistanceResult distance_naive(const Cylinder& a, const Cylinder& b, double tolerance = 1e-12);

}  // namespace mtcs::geometry
