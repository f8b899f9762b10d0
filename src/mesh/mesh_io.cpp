// The CGAL translation unit: polygon-soup I/O for STL, OFF, OBJ and PLY.

#include "mtcs/mesh/mesh_io.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "cad_reader.h"
#include "mesh_file_check.h"

namespace mtcs::mesh {

namespace {

bool is_cad_file(const std::string& path) {
  std::string ext = std::filesystem::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
  return ext == ".step" || ext == ".stp" || ext == ".iges" || ext == ".igs";
}

}  // namespace

bool reads_cad_files() { return cad_available(); }

TriangleMesh read_mesh(const std::string& path) {
  std::error_code unreadable;  // a name too long, a folder without access: no exception, a clear error
  if (!std::filesystem::exists(path, unreadable))
    throw MeshError("mesh file not found: " + path + (unreadable ? " (" + unreadable.message() + ")" : ""));
  if (!std::filesystem::is_regular_file(path, unreadable)) throw MeshError("not a regular file: " + path);
  // Refused before reading: CGAL's readers hold the whole polygon soup in memory.
  if (std::filesystem::file_size(path) > kMaxMeshFileBytes)
    throw MeshError(path + ": " + std::to_string(std::filesystem::file_size(path)) + " bytes, more than the " +
                    std::to_string(kMaxMeshFileBytes) + " bytes a mesh file may have");
  if (is_cad_file(path)) return read_cad(path);
  check_mesh_file(path);
  std::vector<CGAL::Epick::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  bool ok = false;
  try {
    ok = CGAL::IO::read_polygon_soup(path, points, polygons, CGAL::parameters::verbose(false));
  } catch (const std::exception& e) {
    throw MeshError("cannot read mesh " + path + ": " + e.what());
  }
  if (!ok) throw MeshError("cannot read mesh " + path + " (STL, OFF, OBJ or PLY expected, by extension)");
  TriangleMesh m;
  std::size_t triangles = 0;
  for (const auto& poly : polygons) triangles += poly.size() >= 3 ? poly.size() - 2 : 0;
  if (triangles > kMaxMeshTriangles || points.size() > kMaxMeshTriangles)
    throw MeshError(path + ": " + std::to_string(triangles) + " triangles and " + std::to_string(points.size()) +
                    " vertices, more than the " + std::to_string(kMaxMeshTriangles) + " a mesh may have");
  m.vertices.reserve(points.size());
  for (const auto& p : points) m.vertices.emplace_back(p.x(), p.y(), p.z());
  // Binary STL and PLY, which have no lines to name: NaN, infinities, 1e308 by vertex.
  for (std::size_t v = 0; v < m.vertices.size(); ++v)
    for (int k = 0; k < 3; ++k)
      if (!std::isfinite(m.vertices[v][k]) || std::abs(m.vertices[v][k]) > kMaxMeshCoordinate) {
        std::ostringstream value;
        value << m.vertices[v][k];
        throw MeshError(path + ": vertex " + std::to_string(v) + ": coordinate " + "xyz"[k] + " is " + value.str() +
                        ", not a finite number of at most 1e9 in size");
      }
  for (std::size_t f = 0; f < polygons.size(); ++f) {
    const auto& poly = polygons[f];
    if (poly.size() < 3) throw MeshError(path + ": face " + std::to_string(f) + " has fewer than 3 corners");
    for (std::size_t k = 0; k < poly.size(); ++k)
      if (poly[k] >= points.size()) throw MeshError(path + ": face " + std::to_string(f) + " refers to a missing vertex");
    for (std::size_t k = 1; k + 1 < poly.size(); ++k)
      m.triangles.push_back({int(poly[0]), int(poly[k]), int(poly[k + 1])});
  }
  return m;
}

void write_stl(const std::string& path, const TriangleMesh& mesh) {
  std::ofstream out(path, std::ios::binary);
  if (!out) throw MeshError("cannot write " + path);
  char header[80] = "binary STL written by mtcs";
  out.write(header, 80);
  const auto n = std::uint32_t(mesh.triangles.size());
  out.write(reinterpret_cast<const char*>(&n), 4);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Vec3 a = mesh.corner(t, 0), b = mesh.corner(t, 1), c = mesh.corner(t, 2);
    Vec3 normal = (b - a).cross(c - a);
    if (normal.norm() > 0) normal.normalize();
    float buf[12];
    for (int k = 0; k < 3; ++k) {
      buf[k] = float(normal[k]), buf[3 + k] = float(a[k]), buf[6 + k] = float(b[k]), buf[9 + k] = float(c[k]);
    }
    out.write(reinterpret_cast<const char*>(buf), sizeof buf);
    const std::uint16_t attribute = 0;
    out.write(reinterpret_cast<const char*>(&attribute), 2);
  }
  if (!out) throw MeshError("cannot write " + path);
}

}  // namespace mtcs::mesh
