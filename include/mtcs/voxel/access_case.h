#pragma once
// The accessibility-map case files of shared/cases/access_maps (format in its README): a mesh
// with its scaling, the voxel grid, the pivot, the tool, the sphere grid and the expected map.
// Reading keeps every line so that writing reproduces the file with `collisions` and `am`
// replaced.

#include <iosfwd>
#include <string>
#include <vector>

#include "mtcs/mesh/triangle_mesh.h"
#include "mtcs/voxel/accessibility_map.h"
#include "mtcs/voxel/tool.h"
#include "mtcs/voxel/voxel_grid.h"

namespace mtcs::voxel {

struct AccessCase {
  std::string path;  // the file read (for messages)
  std::string mesh;  // as written: relative to the folder holding shared/
  double scale = 1;
  Vec3 centre = Vec3::Zero();
  GridSpec grid;
  long solid_voxels = -1;  // -1 when absent
  long octree_nodes = -1;
  Vec3 pivot = Vec3::Zero();
  int pivot_line = 0;  // 1-based, for messages
  Tool tool;
  SphereGrid sphere;
  long collisions = -1;
  std::vector<std::string> am;  // rows of '0'/'1', empty when absent

  std::vector<std::string> lines;  // the file as read, for writing it back
};

// Throws io::InputError naming file:line:column and the field.
AccessCase read_access_case(const std::string& path);

// Scaled vertex = scale * (file vertex - centre), per component in double.
mesh::TriangleMesh scale_case_mesh(const mesh::TriangleMesh& raw, const AccessCase& c);

// The case file with its `collisions` line and `am` block replaced by `map` (rows of '0'/'1');
// appended when the file had none.
void write_access_case(std::ostream& out, const AccessCase& c, const std::vector<std::string>& map);

// The mesh a case names: `mesh_override` when given; else the case's `mesh` line, relative to
// the folder holding the `shared/` folder the case file lies in (shared/cases/access_maps/X.txt),
// else to the working directory.
std::string resolve_case_mesh(const AccessCase& c, const std::string& mesh_override = "");

// The part as the case has it: the mesh read and scaled as the case says, voxelised on its grid.
// Throws io::InputError for an unreadable or open mesh.
Octree case_octree(const AccessCase& c, const std::string& mesh_path);

struct CaseSolution {
  AccessMap map;
  std::size_t solid_voxels = 0;
  std::size_t octree_nodes = 0;
};

// The case's map: case_octree, then the map of its pivot and tool. Throws io::InputError as
// case_octree does, and for a pivot inside the part (naming the case's pivot line).
CaseSolution solve_access_case(const AccessCase& c, const std::string& mesh_path, const AmOptions& options = {});

}  // namespace mtcs::voxel
