#include "mtcs/mesh/mesh_check.h"

#include "mtcs/mesh/interference.h"

namespace mtcs::mesh {

std::string MeshCheck::message(std::size_t listed) const {
  std::string m = closed_problem;
  if (!self_intersections.empty()) {
    if (!m.empty()) m += "; ";
    m += std::to_string(self_intersections.size()) + " pair(s) of triangles intersect each other without a common corner:";
    for (std::size_t i = 0; i < std::min(listed, self_intersections.size()); ++i)
      m += " " + std::to_string(self_intersections[i][0]) + "-" + std::to_string(self_intersections[i][1]);
    if (self_intersections.size() > listed) m += " ...";
  }
  return m;
}

MeshCheck check_mesh(const TriangleMesh& mesh) {
  MeshCheck c;
  c.closed_problem = closed_mesh_problem(mesh);
  // Self-intersections need well-formed triangles (indices in range, not degenerate).
  if (c.closed_problem.find("missing vertex") != std::string::npos || c.closed_problem.find("degenerate") != std::string::npos ||
      c.closed_problem.find("non-finite") != std::string::npos || mesh.triangles.empty())
    return c;
  c.self_intersections = self_intersections(InterferenceBvh(mesh, split_parts(mesh)));
  return c;
}

}  // namespace mtcs::mesh
