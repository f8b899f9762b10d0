#pragma once
// The accessibility map of a user's part, without a case file: the mesh voxelised on a cubic
// grid of n^3 voxels fitted to its bounding box, and the tools users name (a straight bore, or
// coaxial cylinders).
//
// Grid convention: voxel size = (largest bounding-box extent) / (n - 2), the bounding box centred
// in the grid, so at least one empty voxel layer pads every side of the part.

#include <ostream>
#include <string>

#include "mtcs/mesh/triangle_mesh.h"
#include "mtcs/voxel/accessibility_map.h"
#include "mtcs/voxel/voxel_grid.h"

namespace mtcs::voxel {

// n in [3, 4096]; throws std::invalid_argument otherwise or for an empty or flat-in-all-axes mesh.
GridSpec part_grid(const mesh::TriangleMesh& part, int n);

// A straight bore drilled from the pivot: one cylinder 0 <= t <= length of the given radius.
Tool bore_tool(double radius, double length);

// What is wrong with a tool, or "" when nothing is: no cylinder, non-finite numbers, a < 0,
// b < a, r < 0.
std::string tool_problem(const Tool& tool);

// A tool file: a YAML list of cylinders {a, b, r} (mm along the axis from the pivot, radius).
// Throws io::InputError with file, line, column and field.
Tool read_tool_file(const std::string& path);

// The part's mesh, read and required closed; io::InputError naming the file otherwise.
mesh::TriangleMesh read_part(const std::string& path);

struct PartMap {
  AccessMap map;
  GridSpec grid;
  std::size_t solid_voxels = 0;
  bool pivot_inside = false;  // in the closed box of a solid voxel or inside the mesh: no map
};

// Whether `pivot` is inside the part: in a solid voxel of `tree` (the part on `grid`), or inside
// the mesh itself, which a coarse grid can miss near the surface.
bool pivot_inside(const mesh::TriangleMesh& part, const Octree& tree, const GridSpec& grid, const Vec3& pivot);

// Voxelises `part` (closed, checked by the caller) on part_grid(part, n) and computes the map
// of `tool` pivoting at `pivot` on `sphere`, unless the pivot is inside the part.
PartMap part_access_map(const mesh::TriangleMesh& part, int n, const Vec3& pivot, const Tool& tool, const SphereGrid& sphere,
                        const AmOptions& options = {});

// The map as CSV, one direction a row: phi,gamma (degrees),dx,dy,dz,free (1 free, 0 colliding).
void write_map_csv(std::ostream& out, const AccessMap& map, const SphereGrid& sphere);

}  // namespace mtcs::voxel
