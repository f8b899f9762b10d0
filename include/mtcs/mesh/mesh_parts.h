#pragma once
// The source paper's hierarchy above the triangles: solids (connected components of the mesh)
// and faces (patches: edge-connected regions whose normals stay within an angle of the normal
// of the triangle that started the patch, so a planar CAD face is one patch and a curved one a
// few). Interference results are reported per solid and face.

#include <vector>

#include "mtcs/mesh/triangle_mesh.h"

namespace mtcs::mesh {

struct MeshParts {
  std::vector<int> solid_of;        // per triangle
  std::vector<int> face_of;         // per triangle; faces numbered over the whole mesh
  std::vector<int> solid_of_face;   // per face
  int solids = 0;
  int faces() const { return int(solid_of_face.size()); }
};

MeshParts split_parts(const TriangleMesh& mesh, double face_angle_degrees = 20);

}  // namespace mtcs::mesh
