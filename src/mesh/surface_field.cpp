// Surface fields: uniform refinement and the VTP / PLY writers.

#include "mtcs/mesh/surface_field.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <set>
#include <tuple>

#include "mtcs/mesh/mesh_io.h"

namespace mtcs::mesh {

namespace {

// The index k of the triangle's longest edge (t[k], t[k + 1]); ties to the lowest k, so that the
// marking and the splitting below agree.
int longest_edge(const TriangleMesh& m, const std::array<int, 3>& t) {
  int k = 0;
  double best = -1;
  for (int e = 0; e < 3; ++e) {
    const Vec3& a = m.vertices[std::size_t(t[std::size_t(e)])];
    const double len = (a - m.vertices[std::size_t(t[std::size_t((e + 1) % 3)])]).squaredNorm();
    if (len > best) best = len, k = e;
  }
  return k;
}

}  // namespace

TriangleMesh refine(const TriangleMesh& mesh, double max_edge, int max_split) {
  using Edge = std::pair<int, int>;
  auto key = [](int a, int b) { return a < b ? Edge{a, b} : Edge{b, a}; };
  TriangleMesh out = mesh;
  double longest = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) longest = std::max(longest, (mesh.corner(t, k) - mesh.corner(t, (k + 1) % 3)).norm());
  const double shortest_cut = longest / std::max(1, max_split);  // no shorter edge is marked
  if (!(max_edge > 0) || !(longest > max_edge)) return out;
  auto length = [&](int a, int b) { return (out.vertices[std::size_t(a)] - out.vertices[std::size_t(b)]).norm(); };
  std::map<Edge, int> middle;  // shared by the edge's two triangles: the result stays closed
  auto midpoint = [&](int a, int b) {
    auto [it, fresh] = middle.try_emplace(key(a, b), int(out.vertices.size()));
    if (fresh) out.vertices.push_back(0.5 * (out.vertices[std::size_t(a)] + out.vertices[std::size_t(b)]));
    return it->second;
  };
  // Longest-edge bisection (Rivara): each pass halves every edge still too long; a triangle with
  // any edge to halve halves its longest edge too, so every piece keeps its angles bounded and
  // both triangles of an edge split it at the same point.
  for (int pass = 0; pass < 256; ++pass) {
    std::set<Edge> marked;
    for (const auto& t : out.triangles)
      for (int e = 0; e < 3; ++e) {
        const int a = t[std::size_t(e)], b = t[std::size_t((e + 1) % 3)];
        const double len = length(a, b);
        if (len > max_edge && len > shortest_cut) marked.insert(key(a, b));
      }
    if (marked.empty()) break;
    std::vector<int> longest_of(out.triangles.size());
    for (std::size_t t = 0; t < out.triangles.size(); ++t) longest_of[t] = longest_edge(out, out.triangles[t]);
    for (bool grew = true; grew;) {
      grew = false;
      for (std::size_t i = 0; i < out.triangles.size(); ++i) {
        const auto& t = out.triangles[i];
        const int k = longest_of[i];
        const Edge l = key(t[std::size_t(k)], t[std::size_t((k + 1) % 3)]);
        if (marked.count(l)) continue;
        for (int e = 0; e < 3; ++e)
          if (marked.count(key(t[std::size_t(e)], t[std::size_t((e + 1) % 3)]))) {
            marked.insert(l), grew = true;
            break;
          }
      }
    }
    std::vector<std::array<int, 3>> next;
    next.reserve(2 * out.triangles.size());
    for (std::size_t i = 0; i < out.triangles.size(); ++i) {
      const auto& t = out.triangles[i];
      const int k = longest_of[i];
      const int a = t[std::size_t(k)], b = t[std::size_t((k + 1) % 3)], c = t[std::size_t((k + 2) % 3)];
      if (!marked.count(key(a, b))) {
        next.push_back(t);
        continue;
      }
      const int m = midpoint(a, b);  // children (a, m, c) and (m, b, c), each maybe split once more
      if (marked.count(key(c, a))) {
        const int p = midpoint(c, a);
        next.push_back({a, m, p}), next.push_back({m, c, p});
      } else {
        next.push_back({a, m, c});
      }
      if (marked.count(key(b, c))) {
        const int r = midpoint(b, c);
        next.push_back({m, b, r}), next.push_back({m, r, c});
      } else {
        next.push_back({m, b, c});
      }
    }
    out.triangles = std::move(next);
  }
  return out;
}

namespace {

void check(const SurfaceField& field) {
  if (field.values.size() != field.surface.vertices.size())
    throw MeshError("surface field: " + std::to_string(field.values.size()) + " values for " +
                    std::to_string(field.surface.vertices.size()) + " vertices");
}

}  // namespace

void write_vtp(std::ostream& out, const SurfaceField& field) {
  check(field);
  const TriangleMesh& m = field.surface;
  // The active scalars name the array itself, unit included, or ParaView shows none.
  const std::string array = field.name + (field.unit.empty() ? "" : " [" + field.unit + "]");
  out << std::setprecision(std::numeric_limits<double>::max_digits10);
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"PolyData\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PolyData>\n"
      << "<Piece NumberOfPoints=\"" << m.vertices.size() << "\" NumberOfPolys=\"" << m.triangles.size() << "\">\n"
      << "<PointData Scalars=\"" << array << "\">\n"
      << "<DataArray type=\"Float64\" Name=\"" << array << "\" format=\"ascii\">\n";
  for (double v : field.values) out << v << '\n';
  out << "</DataArray>\n</PointData>\n<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for (const Vec3& v : m.vertices) out << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
  out << "</DataArray>\n</Points>\n<Polys>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for (const auto& t : m.triangles) out << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
  out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  for (std::size_t t = 1; t <= m.triangles.size(); ++t) out << 3 * t << '\n';
  out << "</DataArray>\n</Polys>\n</Piece>\n</PolyData>\n</VTKFile>\n";
}

std::array<unsigned char, 3> color_map(double t) {
  // Viridis at nine stops, linearly interpolated: ordered in lightness, readable in grey.
  static constexpr double stops[9][3] = {{68, 1, 84},    {71, 44, 122},  {59, 81, 139},  {44, 113, 142}, {33, 144, 141},
                                         {39, 173, 129}, {92, 200, 99},  {170, 220, 50}, {253, 231, 37}};
  if (!(t > 0)) t = 0;  // NaN too
  if (t > 1) t = 1;
  const double x = t * 8;
  const int k = std::min(7, int(x));
  const double f = x - k;
  std::array<unsigned char, 3> c{};
  for (int i = 0; i < 3; ++i) c[std::size_t(i)] = static_cast<unsigned char>(std::lround(stops[k][i] + f * (stops[k + 1][i] - stops[k][i])));
  return c;
}

void write_ply(std::ostream& out, const SurfaceField& field, double lo, double hi) {
  check(field);
  const TriangleMesh& m = field.surface;
  const double span = hi > lo ? hi - lo : 1;
  out << std::setprecision(std::numeric_limits<double>::max_digits10);
  out << "ply\nformat ascii 1.0\ncomment written by mtcs\ncomment quality = " << field.name
      << (field.unit.empty() ? "" : " [" + field.unit + "]") << ", colours over [" << lo << ", " << hi << "]\n"
      << "element vertex " << m.vertices.size()
      << "\nproperty double x\nproperty double y\nproperty double z\nproperty uchar red\nproperty uchar green\n"
         "property uchar blue\nproperty float quality\n"
      << "element face " << m.triangles.size() << "\nproperty list uchar int vertex_indices\nend_header\n";
  for (std::size_t v = 0; v < m.vertices.size(); ++v) {
    const auto c = color_map((field.values[v] - lo) / span);
    out << m.vertices[v].x() << ' ' << m.vertices[v].y() << ' ' << m.vertices[v].z() << ' ' << int(c[0]) << ' '
        << int(c[1]) << ' ' << int(c[2]) << ' ' << float(field.values[v]) << '\n';
  }
  for (const auto& t : m.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
}

}  // namespace mtcs::mesh
