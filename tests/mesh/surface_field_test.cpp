// Surface fields: refinement keeps the surface (area, volume, closedness, Euler's formula) and
// the writers give each vertex its value.
#include <catch2/catch.hpp>

#include <sstream>

#include "mtcs/mesh/mesh_io.h"
#include "mtcs/mesh/surface_field.h"

using namespace mtcs::mesh;
using mtcs::geometry::Box;

TEST_CASE("refine splits every triangle alike and keeps the surface closed") {
  const TriangleMesh box = box_mesh(Box{Vec3(0, 0, 0), Vec3(3, 2, 1)});
  const double longest = std::sqrt(13.0);  // the diagonal of the 3 x 2 faces
  const TriangleMesh fine = refine(box, longest / 2.5);  // n = 3
  CHECK(fine.triangles.size() == 12 * 9);
  // Euler: V - E + F = 2 with E = 3F/2.
  CHECK(fine.vertices.size() == 2 + 3 * fine.triangles.size() / 2 - fine.triangles.size());
  CHECK(closed_mesh_problem(fine).empty());
  CHECK(fine.area() == Approx(box.area()).epsilon(1e-14));
  CHECK(fine.signed_volume() == Approx(6.0).epsilon(1e-14));
  CHECK(refine(box, 10).triangles.size() == 12);  // already fine enough
  CHECK(refine(box, 1e-9, 4).triangles.size() == 12 * 16);  // capped
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
