#include "mtcs/mesh/interference_view.h"

#include <algorithm>
#include <map>
#include <tuple>

#include "mtcs/mesh/mesh_io.h"

namespace mtcs::mesh {

std::vector<FaceShape> face_shapes(const TriangleMesh& mesh, const MeshParts& parts) {
  std::vector<FaceShape> shapes(std::size_t(parts.faces()));
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Vec3 &p = mesh.corner(t, 0), &q = mesh.corner(t, 1), &r = mesh.corner(t, 2);
    const double area = 0.5 * (q - p).cross(r - p).norm();
    FaceShape& s = shapes[std::size_t(parts.face_of[t])];
    s.centroid += area * (p + q + r) / 3;
    s.area += area;
  }
  for (FaceShape& s : shapes)
    if (s.area > 0) s.centroid /= s.area;
  return shapes;
}

std::vector<FaceGroup> group_by_face(const InterferenceReport& report, const MeshParts& a, const MeshParts& b) {
  std::map<std::tuple<int, int, int, int>, FaceGroup> groups;
  for (const auto& p : report.pairs) {
    const auto i = std::size_t(p.a), j = std::size_t(p.b);
    const auto key = std::make_tuple(a.solid_of[i], a.face_of[i], b.solid_of[j], b.face_of[j]);
    FaceGroup& g = groups.try_emplace(key, FaceGroup{a.solid_of[i], a.face_of[i], b.solid_of[j], b.face_of[j]}).first->second;
    ++g.pairs, g.penetrating += p.penetrating;
  }
  std::vector<FaceGroup> out;
  for (const auto& [key, g] : groups) out.push_back(g);
  return out;
}

void write_interference_ply(std::ostream& out, const TriangleMesh& a, const TriangleMesh& b,
                            const InterferenceReport& report) {
  TriangleMesh both = a;
  const int offset = int(a.vertices.size());
  both.vertices.insert(both.vertices.end(), b.vertices.begin(), b.vertices.end());
  for (auto t : b.triangles) both.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  std::vector<int> state(both.triangles.size(), 0);
  for (const auto& p : report.pairs) {
    const int s = p.penetrating ? 2 : 1;
    state[std::size_t(p.a)] = std::max(state[std::size_t(p.a)], s);
    state[a.triangles.size() + std::size_t(p.b)] = std::max(state[a.triangles.size() + std::size_t(p.b)], s);
  }
  FaceAttributes faces;
  for (std::size_t t = 0; t < both.triangles.size(); ++t) {
    const bool in_a = t < a.triangles.size();
    faces.colors.push_back(state[t] == 2   ? std::array<unsigned char, 3>{220, 30, 30}
                           : state[t] == 1 ? std::array<unsigned char, 3>{240, 200, 40}
                           : in_a          ? std::array<unsigned char, 3>{170, 170, 170}
                                           : std::array<unsigned char, 3>{90, 140, 220});
    faces.quality.push_back(state[t]);
  }
  write_ply(out, both, faces);
}

}  // namespace mtcs::mesh
