// The cli module's one CGAL translation unit.

#include "cgal_interference_peer.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/intersection.h>
#include <CGAL/Surface_mesh.h>

namespace mtcs::bench {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

struct CgalMesh::Impl {
  CGAL::Surface_mesh<K::Point_3> mesh;
};

CgalMesh::CgalMesh(const mesh::TriangleMesh& m) : impl_(new Impl) {
  std::vector<CGAL::Surface_mesh<K::Point_3>::Vertex_index> v;
  v.reserve(m.vertices.size());
  for (const auto& p : m.vertices) v.push_back(impl_->mesh.add_vertex(K::Point_3(p.x(), p.y(), p.z())));
  for (const auto& t : m.triangles) impl_->mesh.add_face(v[std::size_t(t[0])], v[std::size_t(t[1])], v[std::size_t(t[2])]);
}

CgalMesh::~CgalMesh() = default;
CgalMesh::CgalMesh(CgalMesh&&) noexcept = default;

bool cgal_do_intersect(const CgalMesh& a, const CgalMesh& b) {
  return CGAL::Polygon_mesh_processing::do_intersect(a.impl_->mesh, b.impl_->mesh);
}

}  // namespace mtcs::bench
