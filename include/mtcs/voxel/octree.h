#pragma once
// A pointer-free occupancy octree over a voxel grid: nodes in level order in one array, the
// non-empty children of a mixed node stored contiguously, in octant order (octant o is offset by
// half the node along axis a iff bit a of o is set). Full nodes (every voxel solid) are
// leaves; empty nodes are not stored. The root covers the smallest power-of-two cube of voxels
// holding the grid (voxels outside the grid count as empty).

#include <cstdint>
#include <vector>

#include "mtcs/voxel/voxel_grid.h"

namespace mtcs::voxel {

struct OctreeNode {
  Vec3 centre = Vec3::Zero();              // kept with the node: traversals read both together
  std::array<std::uint16_t, 3> corner{};  // lowest voxel index covered
  std::uint8_t level = 0;                 // 0 = root; `depth` = a single voxel
  std::uint8_t full = 0;                  // 1: every voxel solid (a leaf); 0: mixed
  std::uint8_t child_count = 0;           // non-empty children (mixed nodes only)
  std::uint8_t child_mask = 0;            // bit o: octant o non-empty; children stored by octant
  std::uint32_t first_child = 0;
};

class Octree {
 public:
  explicit Octree(const VoxelGrid& grid);

  const std::vector<OctreeNode>& nodes() const { return nodes_; }
  // Centre and closed box of node i (precomputed).
  const Vec3& node_centre(std::uint32_t i) const { return nodes_[i].centre; }
  const Box& node_box(std::uint32_t i) const { return boxes_[i]; }
  const GridSpec& spec() const { return spec_; }
  int depth() const { return depth_; }
  std::size_t solid_voxels() const { return solid_voxels_; }
  // Nodes of level < L are nodes()[0, level_end(L - 1)).
  std::uint32_t level_end(int level) const { return level_end_[std::size_t(level)]; }

  // Edge length of a node of `level` in voxels and in length units.
  int voxels_across(int level) const { return 1 << (depth_ - level); }
  double edge(int level) const { return spec_.voxel_size * voxels_across(level); }
  // Centre and closed box of a cube given by its corner voxel and level.
  Vec3 centre(const std::array<std::uint16_t, 3>& corner, int level) const;
  Box box(const std::array<std::uint16_t, 3>& corner, int level) const;
  Vec3 centre(const OctreeNode& n) const { return centre(n.corner, n.level); }
  Box box(const OctreeNode& n) const { return box(n.corner, n.level); }

  // True when p lies in the closed box of a solid voxel.
  bool touches_solid(const Vec3& p) const;

 private:
  GridSpec spec_;
  int depth_ = 0;
  std::size_t solid_voxels_ = 0;
  std::vector<OctreeNode> nodes_;
  std::vector<Box> boxes_;
  std::vector<std::uint32_t> level_end_;
};

}  // namespace mtcs::voxel
