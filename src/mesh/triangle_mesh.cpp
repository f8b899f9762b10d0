#include "mtcs/mesh/triangle_mesh.h"

#include <cmath>
#include <unordered_map>

namespace mtcs::mesh {

Box TriangleMesh::bounds() const {
  Box b = Box::empty();
  for (const Vec3& v : vertices) b.min = b.min.cwiseMin(v), b.max = b.max.cwiseMax(v);
  return b;
}

double TriangleMesh::area() const {
  double a = 0;
  for (std::size_t t = 0; t < triangles.size(); ++t)
    a += 0.5 * (corner(t, 1) - corner(t, 0)).cross(corner(t, 2) - corner(t, 0)).norm();
  return a;
}

double TriangleMesh::signed_volume() const {
  double v = 0;
  for (std::size_t t = 0; t < triangles.size(); ++t) v += corner(t, 0).dot(corner(t, 1).cross(corner(t, 2)));
  return v / 6;
}

void TriangleMesh::translate(const Vec3& offset) {
  for (Vec3& v : vertices) v += offset;
}

std::string closed_mesh_problem(const TriangleMesh& mesh) {
  if (mesh.triangles.empty()) return "the mesh has no triangles";
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i)
    if (!mesh.vertices[i].allFinite()) return "vertex " + std::to_string(i) + " has a non-finite coordinate";
  const long nv = long(mesh.vertices.size());
  // Directed edge -> how often it occurs; a closed, oriented 2-manifold has every directed edge
  // once and its reverse once.
  std::unordered_map<long long, int> directed;
  directed.reserve(mesh.triangles.size() * 3);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    for (int k = 0; k < 3; ++k)
      if (tri[k] < 0 || tri[k] >= nv) return "triangle " + std::to_string(t) + " refers to a missing vertex";
    const double twice_area = (mesh.corner(t, 1) - mesh.corner(t, 0)).cross(mesh.corner(t, 2) - mesh.corner(t, 0)).norm();
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2] || !(twice_area > 0))
      return "triangle " + std::to_string(t) + " is degenerate (zero area)";
    for (int k = 0; k < 3; ++k) ++directed[(long long)tri[k] * nv + tri[(k + 1) % 3]];
  }
  for (const auto& [key, count] : directed) {
    const long long a = key / nv, b = key % nv;
    const auto rev = directed.find(b * nv + a);
    if (count > 1) return "edge " + std::to_string(a) + "-" + std::to_string(b) + " is shared by more than two triangles or they are inconsistently oriented";
    if (rev == directed.end()) return "the mesh is not closed: edge " + std::to_string(a) + "-" + std::to_string(b) + " has only one triangle";
  }
  return "";
}

TriangleMesh box_mesh(const Box& b) {
  TriangleMesh m;
  for (int i = 0; i < 8; ++i)
    m.vertices.emplace_back(i & 1 ? b.max.x() : b.min.x(), i & 2 ? b.max.y() : b.min.y(), i & 4 ? b.max.z() : b.min.z());
  // Two triangles per face, counter-clockwise from outside.
  m.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return m;
}

}  // namespace mtcs::mesh
