#include "mtcs/mesh/interference_view.h"

#include <algorithm>
#include <limits>
#include <map>
#include <tuple>
#include <unordered_map>

#include "mtcs/mesh/bvh.h"

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

std::vector<FaceGroup> group_by_face(const InterferenceReport& report, const TriangleMesh& ma, const TriangleMesh& mb,
                                     const MeshParts& a, const MeshParts& b) {
  std::map<std::tuple<int, int, int, int>, FaceGroup> groups;
  for (const auto& p : report.pairs) {
    const auto i = std::size_t(p.a), j = std::size_t(p.b);
    const auto key = std::make_tuple(a.solid_of[i], a.face_of[i], b.solid_of[j], b.face_of[j]);
    FaceGroup& g = groups.try_emplace(key, FaceGroup{a.solid_of[i], a.face_of[i], b.solid_of[j], b.face_of[j]}).first->second;
    ++g.pairs, g.penetrating += p.penetrating;
  }
  std::vector<FaceGroup> out;
  for (const auto& [key, g] : groups) out.push_back(g);
  measure_overlap_depths(out, report, ma, mb, a, b);
  return out;
}

double measure_overlap_depths(std::vector<FaceGroup>& groups, const InterferenceReport& report, const TriangleMesh& a,
                              const TriangleMesh& b, const MeshParts& pa, const MeshParts& pb) {
  if (report.pairs.empty()) return 0;
  const TriangleBvh inside_a(a), inside_b(b);
  // Each vertex's depth in the other solid, computed once (a vertex sits in many pairs).
  std::unordered_map<int, double> depth_in_b, depth_in_a;
  auto depth = [](const TriangleBvh& other, const Vec3& v, std::unordered_map<int, double>& memo, int key) {
    const auto [it, added] = memo.try_emplace(key, 0.0);
    if (added && other.contains(v)) it->second = other.segment_distance(v, v, std::numeric_limits<double>::infinity());
    return it->second;
  };
  std::map<std::tuple<int, int, int, int>, double> deepest;
  for (const auto& p : report.pairs) {
    const auto i = std::size_t(p.a), j = std::size_t(p.b);
    double d = 0;
    for (int k = 0; k < 3; ++k) {
      const int va = a.triangles[i][k], vb = b.triangles[j][k];
      d = std::max({d, depth(inside_b, a.vertices[std::size_t(va)], depth_in_b, va),
                    depth(inside_a, b.vertices[std::size_t(vb)], depth_in_a, vb)});
    }
    double& g = deepest[std::make_tuple(pa.solid_of[i], pa.face_of[i], pb.solid_of[j], pb.face_of[j])];
    g = std::max(g, d);
  }
  double most = 0;
  for (FaceGroup& g : groups) {
    g.depth = deepest[std::make_tuple(g.solid_a, g.face_a, g.solid_b, g.face_b)];
    most = std::max(most, g.depth);
  }
  return most;
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
