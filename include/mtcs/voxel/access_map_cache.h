#pragma once
// Accessibility maps of one part, computed once per (pivot, tool) and kept: an optimiser asks
// for the same drilling entry again and again. Safe to share between threads; a map depends only
// on its key, so which thread computes it first changes nothing (deterministic for any thread
// count). Each map is computed on the calling thread (the callers are already parallel). At
// `max_maps` maps (~1.3 kB each at 32 x 32) the cache starts afresh: memory stays bounded, and
// since a map depends only on its key nothing but time changes.

#include <array>
#include <map>
#include <memory>
#include <mutex>
#include <vector>

#include "mtcs/voxel/accessibility_map.h"
#include "mtcs/voxel/octree.h"

namespace mtcs::voxel {

class AccessMapCache {
 public:
  // The part's octree on `grid`; maps on `sphere` by `method`.
  AccessMapCache(const mesh::TriangleMesh& part, const GridSpec& grid, SphereGrid sphere, AmMethod method = AmMethod::aica,
                 std::size_t max_maps = 50000);

  // The map of `tool` pivoting at `pivot`, keyed by their exact values. Null when the pivot lies
  // in the closed box of a solid voxel (no map: every direction starts inside the part).
  std::shared_ptr<const AccessMap> at(const Vec3& pivot, const Tool& tool) const;

  const Octree& octree() const { return octree_; }
  const SphereGrid& sphere() const { return sphere_; }
  std::size_t size() const;  // maps held

 private:
  using Key = std::vector<double>;  // pivot x, y, z, then a, b, r of each cylinder
  Octree octree_;
  SphereGrid sphere_;
  AmMethod method_;
  std::size_t max_maps_;
  mutable std::mutex mutex_;
  mutable std::map<Key, std::shared_ptr<const AccessMap>> maps_;
};

// The cells of `sphere` a direction lies in, as closed ranges of phi and gamma: row
// floor(phi rows / pi), column floor(gamma cols / 2 pi), gamma = atan2(y, x) in [0, 2 pi); on a
// border (within 1e-9 of a cell) the cells on both sides too, every column at a pole. First the
// cell of the half-open convention, then the others in row-major order.
std::vector<std::array<int, 2>> cells_of(const SphereGrid& sphere, const Vec3& direction);

}  // namespace mtcs::voxel
