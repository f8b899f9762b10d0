// Surface fields: uniform refinement and the VTP / PLY writers.

#include "mtcs/mesh/surface_field.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <map>
#include <tuple>

#include "mtcs/mesh/mesh_io.h"

namespace mtcs::mesh {

TriangleMesh refine(const TriangleMesh& mesh, double max_edge, int max_split) {
  double longest = 0;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) longest = std::max(longest, (mesh.corner(t, k) - mesh.corner(t, (k + 1) % 3)).norm());
  const int cap = std::max(1, max_split);
  const double want = max_edge > 0 ? std::ceil(longest / max_edge) : 1;  // may be huge: clamp as a double
  const int n = want >= cap ? cap : std::max(1, int(want));
  if (n == 1) return mesh;

  TriangleMesh out;
  out.vertices = mesh.vertices;
  // Points inside an edge, shared by its two triangles: keyed by (lower vertex, upper vertex, step
  // from the lower one).
  std::map<std::tuple<int, int, int>, int> on_edge;
  auto edge_point = [&](int a, int b, int i) {  // the i-th of n steps from a to b
    if (i == 0) return a;
    if (i == n) return b;
    const bool flip = a > b;
    const auto key = flip ? std::make_tuple(b, a, n - i) : std::make_tuple(a, b, i);
    auto [it, fresh] = on_edge.try_emplace(key, int(out.vertices.size()));
    if (fresh) {
      const auto [lo, hi, step] = key;
      out.vertices.push_back(mesh.vertices[std::size_t(lo)] +
                             (mesh.vertices[std::size_t(hi)] - mesh.vertices[std::size_t(lo)]) * (double(step) / n));
    }
    return it->second;
  };
  for (const auto& tri : mesh.triangles) {
    const int a = tri[0], b = tri[1], c = tri[2];
    // Barycentric lattice (i steps towards b, j towards c); interior points belong to this triangle.
    std::vector<int> index(std::size_t((n + 1) * (n + 2) / 2));
    auto at = [&](int i, int j) -> int& { return index[std::size_t(j * (2 * n + 3 - j) / 2 + i)]; };
    for (int j = 0; j <= n; ++j)
      for (int i = 0; i + j <= n; ++i) {
        if (j == 0) at(i, j) = edge_point(a, b, i);
        else if (i == 0) at(i, j) = edge_point(a, c, j);
        else if (i + j == n) at(i, j) = edge_point(b, c, j);
        else {
          at(i, j) = int(out.vertices.size());
          const Vec3& pa = mesh.vertices[std::size_t(a)];
          out.vertices.push_back(pa + (mesh.vertices[std::size_t(b)] - pa) * (double(i) / n) +
                                 (mesh.vertices[std::size_t(c)] - pa) * (double(j) / n));
        }
      }
    for (int j = 0; j < n; ++j)
      for (int i = 0; i + j < n; ++i) {
        out.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
        if (i + j + 1 < n) out.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
      }
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
