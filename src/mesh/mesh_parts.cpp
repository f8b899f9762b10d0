#include "mtcs/mesh/mesh_parts.h"

#include <cmath>
#include <numeric>
#include <unordered_map>

namespace mtcs::mesh {
namespace {

int find(std::vector<int>& parent, int x) {
  while (parent[x] != x) x = parent[x] = parent[parent[x]];
  return x;
}

}  // namespace

MeshParts split_parts(const TriangleMesh& mesh, double face_angle_degrees) {
  const std::size_t nt = mesh.triangles.size();
  MeshParts parts;
  // Solids: triangles connected through shared corners.
  std::vector<int> parent(mesh.vertices.size());
  std::iota(parent.begin(), parent.end(), 0);
  for (const auto& t : mesh.triangles) {
    parent[find(parent, t[1])] = find(parent, t[0]);
    parent[find(parent, t[2])] = find(parent, t[0]);
  }
  std::unordered_map<int, int> solid_of_root;
  parts.solid_of.resize(nt);
  for (std::size_t t = 0; t < nt; ++t) {
    const auto [it, fresh] = solid_of_root.try_emplace(find(parent, mesh.triangles[t][0]), int(solid_of_root.size()));
    parts.solid_of[t] = it->second;
  }
  parts.solids = int(solid_of_root.size());

  // Faces: grow patches across shared edges while the normal stays near the seed's.
  std::unordered_map<long long, std::vector<int>> by_edge;
  const auto nv = static_cast<long long>(mesh.vertices.size());
  auto key = [nv](int a, int b) { return a < b ? a * nv + b : b * nv + a; };
  for (std::size_t t = 0; t < nt; ++t)
    for (int k = 0; k < 3; ++k) by_edge[key(mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3])].push_back(int(t));
  std::vector<Vec3> normal(nt);
  for (std::size_t t = 0; t < nt; ++t)
    normal[t] = (mesh.corner(t, 1) - mesh.corner(t, 0)).cross(mesh.corner(t, 2) - mesh.corner(t, 0)).normalized();
  const double min_cos = std::cos(face_angle_degrees * M_PI / 180);
  parts.face_of.assign(nt, -1);
  std::vector<int> queue;
  for (std::size_t seed = 0; seed < nt; ++seed) {
    if (parts.face_of[seed] >= 0) continue;
    const int face = parts.faces();
    parts.solid_of_face.push_back(parts.solid_of[seed]);
    parts.face_of[seed] = face;
    queue.assign(1, int(seed));
    while (!queue.empty()) {
      const int t = queue.back();
      queue.pop_back();
      for (int k = 0; k < 3; ++k)
        for (int n : by_edge[key(mesh.triangles[t][k], mesh.triangles[t][(k + 1) % 3])])
          if (parts.face_of[n] < 0 && normal[n].dot(normal[seed]) >= min_cos) {
            parts.face_of[n] = face;
            queue.push_back(n);
          }
    }
  }
  return parts;
}

}  // namespace mtcs::mesh
