// A user's part on a grid fitted to it, and the tools users name.

#include "mtcs/voxel/part_map.h"

#include <cmath>
#include <stdexcept>

#include "mtcs/voxel/octree.h"

namespace mtcs::voxel {

GridSpec part_grid(const mesh::TriangleMesh& part, int n) {
  if (n < 3 || n > 4096) throw std::invalid_argument("grid must be 3 to 4096 voxels per side, got " + std::to_string(n));
  if (part.vertices.empty()) throw std::invalid_argument("the mesh has no vertices");
  const Box b = part.bounds();
  const double extent = b.size().maxCoeff();
  if (!(extent > 0) || !std::isfinite(extent)) throw std::invalid_argument("the mesh has no extent");
  GridSpec g;
  g.size = {n, n, n};
  g.voxel_size = extent / (n - 2);
  // Centre the bounding box: the grid spans n * voxel_size = extent + 2 voxels on every axis.
  g.origin = 0.5 * (b.min + b.max) - Vec3::Constant(0.5 * n * g.voxel_size);
  return g;
}

Tool bore_tool(double radius, double length) { return {{0, length, radius}}; }

std::string tool_problem(const Tool& tool) {
  if (tool.empty()) return "the tool has no cylinder";
  for (std::size_t i = 0; i < tool.size(); ++i) {
    const ToolCylinder& c = tool[i];
    const std::string at = "cylinder " + std::to_string(i + 1) + ": ";
    if (!std::isfinite(c.a) || !std::isfinite(c.b) || !std::isfinite(c.r)) return at + "non-finite a, b or r";
    if (c.a < 0) return at + "a must be >= 0 (the tool starts at the pivot)";
    if (c.b < c.a) return at + "b must be >= a";
    if (c.r < 0) return at + "r must be >= 0";
  }
  return "";
}

PartMap part_access_map(const mesh::TriangleMesh& part, int n, const Vec3& pivot, const Tool& tool, const SphereGrid& sphere,
                        const AmOptions& options) {
  PartMap out;
  out.grid = part_grid(part, n);
  const Octree tree(voxelize(part, out.grid));
  out.solid_voxels = tree.solid_voxels();
  // In a solid voxel, or inside the mesh itself (a single-voxel grid centred on the pivot, up to
  // one rounding of its centre), which a coarse grid can miss near the surface.
  GridSpec at_pivot;
  at_pivot.size = {1, 1, 1};
  at_pivot.voxel_size = out.grid.voxel_size;
  at_pivot.origin = pivot - Vec3::Constant(0.5 * at_pivot.voxel_size);
  out.pivot_inside = tree.touches_solid(pivot) || voxelize(part, at_pivot).count() > 0;
  if (!out.pivot_inside) out.map = compute_access_map(tree, pivot, tool, sphere, options);
  return out;
}

}  // namespace mtcs::voxel
