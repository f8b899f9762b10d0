// mtcs access-map end to end: a public case rewritten byte for byte by every method; a bad
// case file and a pivot inside the part exit 2 naming file:line and the field, writing nothing.
// The user form (MESH --pivot --bore/--tool): a needle above a cube against the closed form, a
// thicker bore, the PNG, bad input.

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "run_mtcs.h"
#include "support/paths.h"

namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) { return mtcs_test::scratch("access_map_cli", name); }
mtcs_test::Run run_mtcs(const std::string& args) { return mtcs_test::run_mtcs_err("access_map_cli", args); }

// A 4 mm cube centred at the origin as OFF, and a case over it on a 4^3 grid of 2 mm voxels.
std::string cube_case(const fs::path& off, const std::string& pivot) {
  std::ofstream(off) << "OFF\n8 6 0\n-2 -2 -2\n2 -2 -2\n2 2 -2\n-2 2 -2\n-2 -2 2\n2 -2 2\n2 2 2\n-2 2 2\n"
                        "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n4 0 4 7 3\n";
  return "mesh " + off.string() + "\nscale 1\ncentre 0 0 0\ngrid 4 4 4\nvoxel_size 2\ngrid_origin -4 -4 -4\npivot " + pivot +
         "\ntool_cylinders 1\ncyl a 0 b 10 r 1\nam_rows 4\nam_cols 4\n";
}

}  // namespace

TEST_CASE("access-map rewrites a public case byte for byte", "[cli][access-map]") {
  const std::string in = MTCS_TEST_DATA + "/access_maps/drilling_mcad_herringbone_gear_p04.txt";
  for (const std::string method : {"aica", "ica", "checkbox"}) {
    const fs::path out = scratch("am_" + method + ".txt");
    const auto r = run_mtcs("access-map --case " + in + " --mesh " + MTCS_TEST_DATA + "/meshes/mcad_herringbone_gear.off --out " +
                            out.string() + " --method " + method + " --threads 2");
    REQUIRE(r.code == 0);
    CHECK(mtcs_test::read_text(out) == mtcs_test::read_text(in));
  }
}

TEST_CASE("access-map errors exit 2 with file:line and field", "[cli][access-map]") {
  const fs::path off = scratch("cube.off"), bad = scratch("bad.txt"), inside = scratch("inside.txt"), out = scratch("never.txt");
  std::ofstream(bad) << cube_case(off, "0 0 abc");
  auto r = run_mtcs("access-map --case " + bad.string() + " --out " + out.string());
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains(bad.string() + ":7:11: field 'pivot'"));
  std::ofstream(inside) << cube_case(off, "0.5 0.5 0.5");
  r = run_mtcs("access-map --case " + inside.string() + " --out " + out.string());
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains(inside.string() + ":7:1: field 'pivot': the pivot lies inside the part"));
  CHECK_FALSE(fs::exists(out));
  // Outside the cube the map is computed and written (collisions and am appended).
  std::ofstream(inside) << cube_case(off, "0 0 6");
  r = run_mtcs("access-map --case " + inside.string() + " --out " + out.string());
  REQUIRE(r.code == 0);
  const std::string text = mtcs_test::read_text(out);
  // Row 3 of 4 (phi = 157.5 deg) points down into the cube 4 mm below; row 2 (112.5 deg) passes
  // above its far edge (the tool end at z = 2.17, its lowest rim point 9.2 mm out).
  CHECK_THAT(text, Catch::EndsWith("collisions 4\nam\n0000\n0000\n0000\n1111\n"));
}

namespace {

// A 4 mm cube centred at the origin as OFF.
fs::path cube_off() {
  const fs::path off = scratch("user_cube.off");
  std::ofstream(off) << "OFF\n8 6 0\n-2 -2 -2\n2 -2 -2\n2 2 -2\n-2 2 -2\n-2 -2 2\n2 -2 2\n2 2 2\n-2 2 2\n"
                        "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n4 0 4 7 3\n";
  return off;
}

struct Cell {
  double phi, gamma, dx, dy, dz;
  int free;
};

std::vector<Cell> read_cells(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  REQUIRE(line == "phi,gamma,dx,dy,dz,free");
  std::vector<Cell> cells;
  while (std::getline(in, line)) {
    Cell c{};
    REQUIRE(std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf,%d", &c.phi, &c.gamma, &c.dx, &c.dy, &c.dz, &c.free) == 6);
    cells.push_back(c);
  }
  return cells;
}

}  // namespace

TEST_CASE("access-map MESH: a needle above a cube against the closed form", "[cli][access-map]") {
  // Grid 10 over the 4 mm cube: 0.5 mm voxels, one empty layer around it, so the solid voxels
  // are the cube exactly. A radius-0 bore of length 100 from (0, 0, 10) hits it iff the ray
  // crosses the top face z = 2 within |x|, |y| <= 2 (going down, x and y only grow after it).
  const fs::path off = cube_off(), csv = scratch("needle.csv"), tool_csv = scratch("needle_tool.csv"), tool = scratch("needle.yaml");
  auto r = run_mtcs("access-map " + off.string() + " --pivot 0,0,10 --bore 0,100 --grid 10 --am 24,32 --out " + csv.string());
  REQUIRE(r.code == 0);
  const std::vector<Cell> cells = read_cells(csv);
  REQUIRE(cells.size() == 24u * 32u);
  int checked = 0, blocked = 0;
  for (const Cell& c : cells) {
    CHECK(std::abs(c.dx * c.dx + c.dy * c.dy + c.dz * c.dz - 1) < 1e-12);
    CHECK(std::abs(c.dz - std::cos(c.phi * M_PI / 180)) < 1e-12);
    if (c.dz >= 0) {
      CHECK(c.free == 1);
      continue;
    }
    const double t = 8 / -c.dz, x = std::abs(c.dx * t), y = std::abs(c.dy * t);
    if (std::abs(x - 2) < 1e-6 || std::abs(y - 2) < 1e-6) continue;  // grazing an edge: either verdict
    const int expected = x <= 2 && y <= 2 ? 0 : 1;
    CHECK(c.free == expected);
    blocked += 1 - expected;
    ++checked;
  }
  CHECK(checked > 300);
  CHECK(blocked > 10);
  // The same needle as a tool file gives the same map.
  std::ofstream(tool) << "- {a: 0, b: 100, r: 0}\n";
  r = run_mtcs("access-map " + off.string() + " --pivot 0,0,10 --tool " + tool.string() + " --grid 10 --am 24,32 --out " + tool_csv.string());
  REQUIRE(r.code == 0);
  CHECK(mtcs_test::read_text(tool_csv) == mtcs_test::read_text(csv));
}

TEST_CASE("access-map MESH: a thicker bore is blocked more often, a PNG is drawn", "[cli][access-map]") {
  const fs::path off = cube_off(), thin = scratch("thin.csv"), thick = scratch("thick.csv"), png = scratch("am.png");
  REQUIRE(run_mtcs("access-map " + off.string() + " --pivot 0,0,10 --bore 0,100 --grid 10 --am 16,16 --out " + thin.string()).code == 0);
  REQUIRE(run_mtcs("access-map " + off.string() + " --pivot 0,0,10 --bore 1.5,100 --grid 10 --am 16,16 --out " + thick.string()).code == 0);
  const std::vector<Cell> a = read_cells(thin), b = read_cells(thick);
  REQUIRE(a.size() == b.size());
  int fewer = 0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    CHECK(b[k].free <= a[k].free);  // the thick bore contains the needle
    fewer += a[k].free - b[k].free;
  }
  CHECK(fewer > 0);
  if (!mtcs_test::has_matplotlib()) return;
  REQUIRE(run_mtcs("access-map " + off.string() + " --pivot 0,0,10 --bore 1.5,100 --grid 10 --am 16,16 --out " + png.string()).code == 0);
  CHECK(mtcs_test::read_text(png).substr(1, 3) == "PNG");
  CHECK_FALSE(fs::exists(png.string() + ".csv"));
}

TEST_CASE("access-map MESH: bad input exits 2 with a clear message", "[cli][access-map]") {
  const fs::path off = cube_off(), out = scratch("never.csv"), tool = scratch("bad_tool.yaml");
  const std::string base = "access-map " + off.string() + " --grid 10 --out " + out.string();
  auto r = run_mtcs(base + " --pivot 0.5,0.5,0.5 --bore 1,10");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("--pivot 0.5,0.5,0.5 lies inside the part"));
  r = run_mtcs(base + " --pivot 1,x,3 --bore 1,10");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("--pivot: 'x' is not a finite number (expected x,y,z)"));
  r = run_mtcs(base + " --pivot 1,2 --bore 1,10");
  CHECK(r.code == 2);
  // CLI11 counts the comma list (->expected(3)).
  CHECK_THAT(r.err, Catch::Contains("--pivot: At least 3 required but received 2"));
  r = run_mtcs(base + " --pivot 0,0,10 --bore -1,10");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("--bore: radius and length must be >= 0"));
  r = run_mtcs(base + " --pivot 0,0,10");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("exactly one of --bore"));
  r = run_mtcs(base + " --pivot 0,0,10 --bore 1,10 --am 0,8");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("--am: rows and cols must be whole numbers"));
  std::ofstream(tool) << "- {a: 0, b: 10, r: 1}\n- {a: 20, b: 5, r: 1}\n";
  r = run_mtcs("access-map " + off.string() + " --pivot 0,0,10 --tool " + tool.string() + " --out " + out.string());
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains(tool.string() + ":2:"));
  CHECK_THAT(r.err, Catch::Contains("tool[1].b"));
  std::ofstream(tool) << "- {a: 0, b: 10, radius: 1}\n";
  r = run_mtcs("access-map " + off.string() + " --pivot 0,0,10 --tool " + tool.string() + " --out " + out.string());
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains(tool.string() + ":1:"));
  r = run_mtcs("access-map " + off.string() + " --case " + off.string() + " --out " + out.string());
  CHECK(r.code == 2);
  CHECK_FALSE(fs::exists(out));
}
