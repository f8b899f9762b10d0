// A case file's map from its mesh: resolve, read, scale, voxelise, compute.

#include <filesystem>
#include <stdexcept>

#include "mtcs/io/input_error.h"
#include "mtcs/mesh/mesh_io.h"
#include "mtcs/voxel/access_case.h"
#include "mtcs/voxel/part_map.h"

namespace mtcs::voxel {

namespace fs = std::filesystem;

std::string resolve_case_mesh(const AccessCase& c, const std::string& mesh_override) {
  if (!mesh_override.empty()) return mesh_override;
  const fs::path mesh(c.mesh);
  if (mesh.is_absolute()) return c.mesh;
  for (fs::path dir = fs::absolute(c.path).parent_path(); !dir.empty() && dir != dir.root_path(); dir = dir.parent_path())
    if (dir.filename() == "shared" && fs::exists(dir.parent_path() / mesh)) return (dir.parent_path() / mesh).string();
  return c.mesh;
}

Octree case_octree(const AccessCase& c, const std::string& mesh_path) {
  return Octree(voxelize(scale_case_mesh(read_part(mesh_path), c), c.grid));
}

CaseSolution solve_access_case(const AccessCase& c, const std::string& mesh_path, const AmOptions& options) {
  const Octree tree = case_octree(c, mesh_path);
  if (tree.touches_solid(c.pivot))
    throw io::InputError(c.path, c.pivot_line, 1, "pivot", "the pivot lies inside the part (in a solid voxel)");
  CaseSolution s{compute_access_map(tree, c.pivot, c.tool, c.sphere, options), tree.solid_voxels(), tree.nodes().size()};
  return s;
}

}  // namespace mtcs::voxel
