#pragma once
// The molded part as the steel around it sees it, for distances from a bore: the box of a
// primitive cavity (no mesh code), the two triangles of a patch on a block face, or the BVH of a
// mesh cavity. Shared by the clearance stage and the design rules.

#include <optional>
#include <vector>

#include "mtcs/geometry/primitives.h"
#include "mtcs/mesh/bvh.h"
#include "mtcs/mold/scene.h"
#include "exact_cache.h"

namespace mtcs::eval {

class CavitySolid {
 public:
  explicit CavitySolid(const mold::Scene& scene);  // needs the spec's cavity
  // The exact solid-cylinder distance from `hole` to the part, with `bound` as upper bound (a
  // distance at or above it is only said to be clear).
  CachedClearance distance(const geometry::Cylinder& hole, double bound) const;
  const char* kind() const;  // box, patch, mesh
  const std::optional<geometry::Box>& box() const { return box_; }

 private:
  std::optional<geometry::Box> box_;
  std::vector<geometry::Triangle> patch_;  // a patch on a block face: its two triangles
  const mesh::TriangleBvh* bvh_;
};

}  // namespace mtcs::eval
