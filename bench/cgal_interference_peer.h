#pragma once
// CGAL 5.5's Polygon_mesh_processing::do_intersect between two meshes (exact predicates,
// surfaces only), the second peer of mtcs interfere in benchmarks.

#include <memory>

#include "mtcs/mesh/triangle_mesh.h"

namespace mtcs::bench {

class CgalMesh {
 public:
  explicit CgalMesh(const mesh::TriangleMesh& mesh);  // a Surface_mesh copy
  ~CgalMesh();
  CgalMesh(CgalMesh&&) noexcept;
  friend bool cgal_do_intersect(const CgalMesh& a, const CgalMesh& b);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

bool cgal_do_intersect(const CgalMesh& a, const CgalMesh& b);

}  // namespace mtcs::bench
