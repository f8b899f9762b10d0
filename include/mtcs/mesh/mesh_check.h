#pragma once
// Validation of a mesh that must bound a solid: the closedness checks of closed_mesh_problem
// and the self-intersections (triangles without a common corner that meet, found with the
// interference hierarchy and the exact triangle test).

#include <array>
#include <string>
#include <vector>

#include "mtcs/mesh/triangle_mesh.h"

namespace mtcs::mesh {

struct MeshCheck {
  std::string closed_problem;                        // "" when closed, manifold and oriented
  std::vector<std::array<int, 2>> self_intersections;  // triangle index pairs, ordered
  bool ok() const { return closed_problem.empty() && self_intersections.empty(); }
  // One message naming what is wrong (the first `listed` self-intersecting pairs), "" when ok.
  std::string message(std::size_t listed = 5) const;
};

MeshCheck check_mesh(const TriangleMesh& mesh);

}  // namespace mtcs::mesh
