// Surface fields: refinement keeps the surface (area, volume, closedness, Euler's formula) and
// the writers give each vertex its value.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "mtcs/mesh/mesh_io.h"
#include "mtcs/mesh/surface_field.h"

using namespace mtcs::mesh;
using mtcs::geometry::Box;

TEST_CASE("refine bisects to the edge asked for and keeps the surface closed") {
  const TriangleMesh box = box_mesh(Box{Vec3(0, 0, 0), Vec3(3, 2, 1)});
  const TriangleMesh fine = refine(box, 0.4);
  double longest = 0, shortest = 1e9;
  for (std::size_t t = 0; t < fine.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const double e = (fine.corner(t, k) - fine.corner(t, (k + 1) % 3)).norm();
      longest = std::max(longest, e), shortest = std::min(shortest, e);
    }
  CHECK(longest <= 0.4);
  CHECK(shortest >= 0.1);  // bisection: never below a quarter of the edge asked for here
  // Euler: V - E + F = 2 with E = 3F/2; closed, oriented, the same area and volume.
  CHECK(fine.vertices.size() == 2 + 3 * fine.triangles.size() / 2 - fine.triangles.size());
  CHECK(closed_mesh_problem(fine).empty());
  CHECK(fine.area() == Approx(box.area()).epsilon(1e-13));
  CHECK(fine.signed_volume() == Approx(6.0).epsilon(1e-13));
  CHECK(refine(box, 10).triangles.size() == 12);  // already fine enough
  // Capped: it stops once no edge is longer than the longest / max_split.
  const TriangleMesh capped = refine(box, 1e-9, 4);
  double capped_longest = 0;
  for (std::size_t t = 0; t < capped.triangles.size(); ++t)
    for (int k = 0; k < 3; ++k)
      capped_longest = std::max(capped_longest, (capped.corner(t, k) - capped.corner(t, (k + 1) % 3)).norm());
  CHECK(capped_longest <= std::sqrt(13.0) / 4);
  CHECK(capped.triangles.size() <= 12 * 16);
  CHECK(closed_mesh_problem(capped).empty());
}

TEST_CASE("refine leaves small triangles as they are: a thin slab's rim") {
  // 100 x 100 x 1: with one split count for the whole mesh, the 1 mm rim faces would be cut as
  // finely as the 141 mm diagonals; bisection cuts each face to the edge asked for.
  const TriangleMesh slab = box_mesh(Box{Vec3(0, 0, 0), Vec3(100, 100, 1)});
  const TriangleMesh fine = refine(slab, 5);
  CHECK(closed_mesh_problem(fine).empty());
  CHECK(fine.area() == Approx(slab.area()).epsilon(1e-13));
  // The rim (faces across x or y): uniform splitting (n = 29) made 8 x 841 = 6 728 triangles of
  // it; bisection ~1 900 (its long edges are split as the large faces split them).
  std::size_t rim = 0;
  for (std::size_t t = 0; t < fine.triangles.size(); ++t) {
    const Vec3 n = (fine.corner(t, 1) - fine.corner(t, 0)).cross(fine.corner(t, 2) - fine.corner(t, 0));
    if (std::abs(n.z()) < 1e-9 * n.norm()) ++rim;
  }
  CHECK(rim < 2500);
}

TEST_CASE("write_vtp writes one value per point and the polygons") {
  SurfaceField f{box_mesh(Box{Vec3(0, 0, 0), Vec3(1, 1, 1)}), {}, "temperature", "degC"};
  for (std::size_t v = 0; v < f.surface.vertices.size(); ++v) f.values.push_back(20.0 + double(v));
  std::ostringstream out;
  write_vtp(out, f);
  const std::string s = out.str();
  CHECK(s.find("NumberOfPoints=\"8\" NumberOfPolys=\"12\"") != std::string::npos);
  CHECK(s.find("Name=\"temperature [degC]\"") != std::string::npos);
  CHECK(s.find("Scalars=\"temperature [degC]\"") != std::string::npos);  // the active scalars name an array that exists
  // The point data: the eight values in order, right after their DataArray tag.
  std::istringstream data(s.substr(s.find('>', s.find("Name=\"temperature")) + 1));
  for (int v = 0; v < 8; ++v) {
    double x = 0;
    data >> x;
    CHECK(x == 20.0 + v);
  }
  f.values.pop_back();
  CHECK_THROWS_AS(write_vtp(out, f), MeshError);
}

TEST_CASE("write_ply colours by the map and keeps the value as quality") {
  SurfaceField f{box_mesh(Box{Vec3(0, 0, 0), Vec3(1, 1, 1)}), std::vector<double>(8, 30.0), "temperature", "degC"};
  f.values[0] = 10;
  std::ostringstream out;
  write_ply(out, f, 10, 30);
  std::istringstream in(out.str());
  std::string line;
  while (std::getline(in, line) && line != "end_header") {
  }
  double x, y, z, q;
  int r, g, b;
  in >> x >> y >> z >> r >> g >> b >> q;
  const auto low = color_map(0);
  CHECK((r == low[0] && g == low[1] && b == low[2]));
  CHECK(q == 10);
  in >> x >> y >> z >> r >> g >> b >> q;
  const auto high = color_map(1);
  CHECK((r == high[0] && g == high[1] && b == high[2]));
  CHECK(color_map(std::nan("")) == color_map(0));
}
