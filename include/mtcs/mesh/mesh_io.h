#pragma once
// Reading and writing triangle meshes: STL (ASCII and binary), OFF, OBJ and PLY through CGAL's
// I/O. The only place in mtcs that includes CGAL's I/O headers.

#include <stdexcept>
#include <string>

#include "mtcs/mesh/triangle_mesh.h"

namespace mtcs::mesh {

class MeshError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads a polygon mesh (faces with more than three corners are fanned into triangles, which is
// right for the convex faces CAD exporters write). Throws MeshError naming the file.
TriangleMesh read_mesh(const std::string& path);

// Binary STL.
void write_stl(const std::string& path, const TriangleMesh& mesh);

}  // namespace mtcs::mesh
