// Bad numbers in mesh files (issue 15, item 5): NaN, infinities, 1e308 and 1e400 in every
// format are refused by the reader, at their line and column where the format has lines (OFF,
// OBJ, ASCII STL) and by vertex where it has none (binary STL and PLY); denormals and -0 are
// read exactly; 0-area and duplicated triangles are read as written and named by the mesh
// check; a binary STL header promising 10 million triangles that the file does not hold is
// named; a mesh of 400 000 triangles reads.

#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <tuple>

#include "mtcs/mesh/mesh_io.h"
#include "support/scratch_file.h"
#include "support/thrown_by.h"

using mtcs::mesh::MeshError;
using mtcs::mesh::read_mesh;
namespace fs = std::filesystem;

namespace {

std::string write(const std::string& name, const std::string& text) {
  return mtcs_test::write_scratch("mesh_bad_numbers", name, text).string();
}

std::string error_of(const std::string& path) {
  return mtcs_test::thrown_by<MeshError>([&] { read_mesh(path); }, path).what();
}

// A tetrahedron whose vertex 2 has the y coordinate Y, in each text format.
std::string off(const std::string& y) { return "OFF\n4 4 0\n0 0 0\n1 0 0\n0 " + y + " 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"; }
std::string obj(const std::string& y) { return "# tetra\nv 0 0 0\nv 1 0 0\nv 0 " + y + " 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"; }
std::string stl(const std::string& y) {
  const std::string a = "0 0 0", b = "1 0 0", c = "0 " + y + " 0", d = "0 0 1";
  std::string s = "solid t\n";
  for (const auto& [p, q, r] : {std::array{a, c, b}, std::array{a, b, d}, std::array{a, d, c}, std::array{b, c, d}})
    s += "facet normal 0 0 0\nouter loop\nvertex " + p + "\nvertex " + q + "\nvertex " + r + "\nendloop\nendfacet\n";
  return s + "endsolid t\n";
}
std::string ply(const std::string& y) {
  return "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\nproperty double z\n"
         "element face 4\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 " + y +
         " 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
}

// A binary STL of the tetrahedron with vertex (0, y, 0) as floats, or with a header count of its own.
std::string binary_stl(float y, std::uint32_t count = 4) {
  std::string s(80, ' ');
  s.append(reinterpret_cast<const char*>(&count), 4);
  const float p[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, y, 0}, {0, 0, 1}};
  const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (const auto& f : faces) {
    float buf[12] = {};
    for (int c = 0; c < 3; ++c) std::memcpy(buf + 3 + 3 * c, p[f[c]], 12);
    s.append(reinterpret_cast<const char*>(buf), 48);
    s.append(2, '\0');
  }
  return s;
}

// A binary little-endian PLY of the tetrahedron with vertex (0, y, 0) as doubles.
std::string binary_ply(double y) {
  std::string s = "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
                  "property double z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n";
  const double p[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, y, 0}, {0, 0, 1}};
  s.append(reinterpret_cast<const char*>(p), sizeof p);
  const int faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (const auto& f : faces) {
    s += char(3);
    s.append(reinterpret_cast<const char*>(f), 12);
  }
  return s;
}

}  // namespace

TEST_CASE("mesh bad numbers: NaN, infinities, 1e308 and 1e400 are refused at their line and column", "[mesh][bad-numbers]") {
  for (const std::string y : {"nan", "NaN", "-nan", "inf", "-inf", "infinity", "1e400", "1e308", "-1.7e308", "2e9"}) {
    INFO(y);
    // Vertex 2, coordinate y: OFF line 5 column 3, OBJ line 4 column 5, STL line 5 column 10
    // (its second vertex line is vertex 1 of the file's corners: a, c, b).
    CHECK_THAT(error_of(write("t.off", off(y))),
               Catch::Contains("t.off:5:3: vertex 2: coordinate y is '" + y + "', not a finite number of at most 1e9"));
    CHECK_THAT(error_of(write("t.obj", obj(y))), Catch::Contains("t.obj:4:5: vertex 2: coordinate y is '" + y + "'"));
    CHECK_THAT(error_of(write("t.stl", stl(y))), Catch::Contains("t.stl:5:10: vertex 1: coordinate y is '" + y + "'"));
    // ASCII PLY: refused by CGAL's reader or by vertex, never read.
    const std::string p = write("t.ply", ply(y));
    CHECK_THAT(error_of(p), Catch::Contains(p));
  }
}

TEST_CASE("mesh bad numbers: binary STL and PLY refuse NaN, infinities and 1e38 by vertex", "[mesh][bad-numbers]") {
  for (const float y : {std::nanf(""), INFINITY, -INFINITY, 1e38f, -2e9f}) {
    INFO(y);
    const std::string s = write("b.stl", binary_stl(y));
    // Corner 1 of triangle 0 is (0, y, 0).
    CHECK_THAT(error_of(s), Catch::StartsWith(s + ": triangle 0, corner 1: coordinate y is ") &&
                                Catch::Contains("not a finite number of at most 1e9 in size"));
  }
  for (const double y : {std::nan(""), HUGE_VAL, 1e308}) {
    INFO(y);
    const std::string p = write("b.ply", binary_ply(y));
    CHECK_THAT(error_of(p), Catch::StartsWith(p + ": vertex 2: coordinate y is"));
  }
}

TEST_CASE("mesh bad numbers: denormals and -0 are read exactly in every format", "[mesh][bad-numbers]") {
  // The smallest float denormal (1.4e-45) in binary STL, as float; -0 reads as a zero (not in
  // STL: its reader merges the corner (0, -0, 0) with (0, 0, 0), rightly).
  const float tiny = std::numeric_limits<float>::denorm_min();
  for (const auto& [name, text, expected] :
       {std::tuple{"d.off", off("4.9e-324"), 4.9e-324}, std::tuple{"d.obj", obj("1e-310"), 1e-310},
        std::tuple{"d.ply", ply("-0"), 0.0}, std::tuple{"d.stl", stl("1e-310"), 1e-310},
        std::tuple{"db.stl", binary_stl(tiny), double(tiny)}, std::tuple{"db.ply", binary_ply(-0.0), 0.0},
        std::tuple{"dbd.ply", binary_ply(4.9e-324), 4.9e-324}}) {
    INFO(name);
    const auto m = read_mesh(write(name, text));
    REQUIRE(m.vertices.size() == 4);
    REQUIRE(m.triangles.size() == 4);
    bool found = false;  // the vertex (0, y, 0): STL readers may order vertices as they like
    for (const auto& v : m.vertices) found = found || (v.x() == 0 && v.z() == 0 && v.y() == expected);  // -0 == 0
    CHECK(found);
  }
}

TEST_CASE("mesh bad numbers: a binary STL header promising what the file does not hold is named", "[mesh][bad-numbers]") {
  const auto t0 = std::chrono::steady_clock::now();
  // 10 million triangles promised in a file of 284 bytes: named at once, nothing allocated.
  const std::string promised = write("promise.stl", binary_stl(1, 10'000'000));
  CHECK(error_of(promised) == promised + ": the binary STL header promises 10000000 triangles (500000084 bytes), the file has 284 bytes");
  // Beyond the reader's limit of 2e7 triangles: the limit is named.
  const std::string beyond = write("beyond.stl", binary_stl(1, 4'000'000'000u));
  CHECK(error_of(beyond) == beyond + ": the binary STL header promises 4000000000 triangles, more than the 20000000 a mesh may have");
  CHECK_THAT(error_of(write("short.stl", std::string(50, 'x'))), Catch::Contains("too short for a binary STL"));
  CHECK(std::chrono::steady_clock::now() - t0 < std::chrono::seconds(2));
}

TEST_CASE("mesh bad numbers: a binary STL of 400 000 triangles reads", "[mesh][bad-numbers]") {
  // A 200 x 1000 grid of quads on a plane, two triangles each: 400 000 triangles, 20 MB.
  constexpr int kX = 200, kY = 1000;
  const std::uint32_t n = 2 * kX * kY;
  std::string s(80, ' ');
  s.append(reinterpret_cast<const char*>(&n), 4);
  s.reserve(84 + 50 * std::size_t(n));
  auto add = [&](const float (&a)[3], const float (&b)[3], const float (&c)[3]) {
    float buf[12] = {0, 0, 1};
    std::memcpy(buf + 3, a, 12), std::memcpy(buf + 6, b, 12), std::memcpy(buf + 9, c, 12);
    s.append(reinterpret_cast<const char*>(buf), 48);
    s.append(2, '\0');
  };
  for (int i = 0; i < kX; ++i)
    for (int j = 0; j < kY; ++j) {
      const float x0 = float(i), x1 = float(i + 1), y0 = float(j), y1 = float(j + 1);
      add({x0, y0, 0}, {x1, y0, 0}, {x1, y1, 0});
      add({x0, y0, 0}, {x1, y1, 0}, {x0, y1, 0});
    }
  const std::string path = write("grid.stl", s);
  const auto t0 = std::chrono::steady_clock::now();
  const auto m = read_mesh(path);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  INFO("400 000 triangles read in " << seconds << " s");
  CHECK(m.triangles.size() == n);
  CHECK(m.vertices.size() == std::size_t(kX + 1) * (kY + 1));  // shared corners merged
  CHECK(seconds < 20);
  fs::remove(path);
}

TEST_CASE("mesh bad numbers: 0-area and duplicated triangles are read as written and named by the mesh check",
          "[mesh][bad-numbers]") {
  // A tetrahedron with its last triangle twice.
  const auto twice = read_mesh(write("twice.off", off("1") + "3 1 2 3\n"));
  CHECK(twice.triangles.size() == 4);  // the header says 4 faces: the fifth line is not read
  const auto five = read_mesh(write("five.off", "OFF\n4 5 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n3 1 2 3\n"));
  CHECK(five.triangles.size() == 5);
  CHECK_THAT(mtcs::mesh::closed_mesh_problem(five), Catch::Contains("more than two triangles"));
  // A triangle of three corners on a line: zero area.
  const auto flat = read_mesh(write("flat.obj", obj("1") + "v 0.5 0 0\nf 1 5 2\n"));
  CHECK(flat.triangles.size() == 5);
  CHECK_THAT(mtcs::mesh::closed_mesh_problem(flat), Catch::Contains("degenerate (zero area)"));
}
