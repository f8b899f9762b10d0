// Octree construction in level order from a summed-volume table: the solid count of any cube
// is eight lookups, so each node's state costs O(1).

#include "mtcs/voxel/octree.h"

#include <algorithm>
#include <stdexcept>

namespace mtcs::voxel {
namespace {

// Summed-volume table over the padded cube: sat(i, j, k) = solid voxels with index < (i, j, k).
class SummedVolume {
 public:
  SummedVolume(const VoxelGrid& grid, int side) : n_(side + 1), sum_(std::size_t(n_) * n_ * n_, 0) {
    const auto& s = grid.spec.size;
    for (int k = 1; k < n_; ++k)
      for (int j = 1; j < n_; ++j)
        for (int i = 1; i < n_; ++i) {
          const bool solid = i <= s[0] && j <= s[1] && k <= s[2] && grid.at(i - 1, j - 1, k - 1);
          ref(i, j, k) = std::int32_t(std::int64_t(solid) + at(i - 1, j, k) + at(i, j - 1, k) + at(i, j, k - 1) -
                                      at(i - 1, j - 1, k) - at(i - 1, j, k - 1) - at(i, j - 1, k - 1) + at(i - 1, j - 1, k - 1));
        }
  }
  std::int64_t count(int i, int j, int k, int w) const {
    return at(i + w, j + w, k + w) - at(i, j + w, k + w) - at(i + w, j, k + w) - at(i + w, j + w, k) +
           at(i, j, k + w) + at(i, j + w, k) + at(i + w, j, k) - at(i, j, k);
  }

 private:
  std::int32_t& ref(int i, int j, int k) { return sum_[(std::size_t(k) * n_ + j) * n_ + i]; }
  std::int64_t at(int i, int j, int k) const { return sum_[(std::size_t(k) * n_ + j) * n_ + i]; }
  int n_;
  std::vector<std::int32_t> sum_;  // counts < 2^31 up to 1024^3; sums taken in 64 bits
};

}  // namespace

Octree::Octree(const VoxelGrid& grid) : spec_(grid.spec) {
  const int largest = std::max({spec_.size[0], spec_.size[1], spec_.size[2], 1});
  while ((1 << depth_) < largest) ++depth_;
  if (depth_ > 10) throw std::invalid_argument("octree: grid larger than 1024 voxels across");
  const int side = 1 << depth_;
  const SummedVolume sat(grid, side);
  solid_voxels_ = std::size_t(sat.count(0, 0, 0, side));
  if (solid_voxels_ > 0) {
    OctreeNode root;
    root.full = std::int64_t(solid_voxels_) == std::int64_t(side) * side * side;
    nodes_.push_back(root);
  }
  level_end_.assign(std::size_t(depth_) + 1, 0);
  std::size_t begin = 0;
  for (int level = 0; level <= depth_; ++level) {
    const std::size_t end = nodes_.size();
    level_end_[std::size_t(level)] = std::uint32_t(end);
    const int w = level < depth_ ? voxels_across(level + 1) : 0;  // child edge in voxels
    for (std::size_t n = begin; n < end && level < depth_; ++n) {
      if (nodes_[n].full) continue;
      nodes_[n].first_child = std::uint32_t(nodes_.size());
      for (int c = 0; c < 8; ++c) {
        OctreeNode child;
        for (int a = 0; a < 3; ++a) child.corner[std::size_t(a)] = std::uint16_t(nodes_[n].corner[std::size_t(a)] + ((c >> a) & 1) * w);
        child.level = std::uint8_t(level + 1);
        const std::int64_t solid = sat.count(child.corner[0], child.corner[1], child.corner[2], w);
        if (solid == 0) continue;
        child.full = solid == std::int64_t(w) * w * w;
        nodes_.push_back(child);
        ++nodes_[n].child_count;
        nodes_[n].child_mask = std::uint8_t(nodes_[n].child_mask | (1u << c));
      }
    }
    begin = end;
  }
  boxes_.reserve(nodes_.size());
  for (OctreeNode& n : nodes_) {
    n.centre = centre(n.corner, n.level);
    boxes_.push_back(box(n));
  }
}

Vec3 Octree::centre(const std::array<std::uint16_t, 3>& corner, int level) const {
  const double half = 0.5 * voxels_across(level);
  Vec3 c;
  for (int a = 0; a < 3; ++a) c[a] = spec_.origin[a] + (corner[std::size_t(a)] + half) * spec_.voxel_size;
  return c;
}

Box Octree::box(const std::array<std::uint16_t, 3>& corner, int level) const {
  const int w = voxels_across(level);
  Box b;
  for (int a = 0; a < 3; ++a) {
    b.min[a] = spec_.origin[a] + corner[std::size_t(a)] * spec_.voxel_size;
    b.max[a] = spec_.origin[a] + (corner[std::size_t(a)] + w) * spec_.voxel_size;
  }
  return b;
}

bool Octree::touches_solid(const Vec3& p) const {
  if (nodes_.empty()) return false;
  std::vector<std::uint32_t> stack{0};
  while (!stack.empty()) {
    const OctreeNode& n = nodes_[stack.back()];
    stack.pop_back();
    if (!box(n).contains(p)) continue;
    if (n.full) return true;
    for (std::uint32_t c = 0; c < n.child_count; ++c) stack.push_back(n.first_child + c);
  }
  return false;
}

}  // namespace mtcs::voxel
