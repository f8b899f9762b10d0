#pragma once
// A regular grid of voxels and the voxelisation of a closed mesh on it: voxel (i, j, k) has its
// centre at origin + (i + 0.5, j + 0.5, k + 0.5) * voxel_size and is solid iff that centre lies
// strictly inside the mesh (winding number != 0), decided with exact predicates.

#include <array>
#include <cstdint>
#include <vector>

#include "mtcs/geometry/primitives.h"
#include "mtcs/geometry/triangle_distance.h"
#include "mtcs/mesh/triangle_mesh.h"

namespace mtcs::voxel {

using geometry::Box;
using geometry::Vec3;

struct GridSpec {
  std::array<int, 3> size{0, 0, 0};  // voxels along x, y, z
  double voxel_size = 1;
  Vec3 origin = Vec3::Zero();

  // Coordinate of voxel centre `i` along `axis`, evaluated as the convention states.
  double centre(int axis, int i) const { return origin[axis] + (i + 0.5) * voxel_size; }
};

struct VoxelGrid {
  GridSpec spec;
  std::vector<std::uint8_t> solid;  // x fastest, then y, then z

  std::size_t index(int i, int j, int k) const {
    return (std::size_t(k) * std::size_t(spec.size[1]) + std::size_t(j)) * std::size_t(spec.size[0]) + std::size_t(i);
  }
  bool at(int i, int j, int k) const { return solid[index(i, j, k)] != 0; }
  std::size_t count() const;
  // The closed cube of voxel (i, j, k).
  Box voxel_box(int i, int j, int k) const;
};

// Exact voxelisation: for every column of centres along x, the generalised winding number by
// signed crossings of a ray in +x whose start is perturbed symbolically (so rays through
// vertices and edges count every crossing once), and centres on the surface found exactly and
// left empty. The mesh must be closed and consistently oriented (either way round).
VoxelGrid voxelize(const mesh::TriangleMesh& mesh, const GridSpec& spec);

}  // namespace mtcs::voxel
