#pragma once
// The 60 public accessibility-map cases (tests/data/access_maps, copied from
// shared/cases/access_maps) and their meshes (tests/data/meshes, the same files as
// shared/molds_data), with the voxel octree of each mesh built once per test binary.

#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "mtcs/mesh/mesh_io.h"
#include "mtcs/voxel/access_case.h"
#include "mtcs/voxel/octree.h"
#include "support/paths.h"

namespace mtcs::voxel::testing {

inline std::vector<std::string> case_paths() {
  std::vector<std::string> paths;
  for (const auto& e : std::filesystem::directory_iterator(std::string(MTCS_TEST_DATA) + "/access_maps"))
    if (e.path().extension() == ".txt") paths.push_back(e.path().string());
  std::sort(paths.begin(), paths.end());
  return paths;
}

// The case's mesh (its `mesh` line names shared/molds_data/NAME.off; the copy is in
// tests/data/meshes), scaled as the case says.
inline mesh::TriangleMesh case_mesh(const AccessCase& c) {
  const std::string name = std::filesystem::path(c.mesh).filename().string();
  return scale_case_mesh(mesh::read_mesh(std::string(MTCS_TEST_DATA) + "/meshes/" + name), c);
}

// Every case of one mesh shares scale, centre and grid: build its octree once.
inline const Octree& case_octree(const AccessCase& c) {
  static std::map<std::string, std::unique_ptr<Octree>> cache;
  auto& slot = cache[c.mesh];
  if (!slot) slot = std::make_unique<Octree>(voxelize(case_mesh(c), c.grid));
  return *slot;
}

}  // namespace mtcs::voxel::testing
