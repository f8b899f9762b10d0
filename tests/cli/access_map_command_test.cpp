// mtcs access-map end to end: a public case rewritten byte for byte by every method; a bad
// case file and a pivot inside the part exit 2 naming file:line and the field, writing nothing.

#include <catch2/catch.hpp>
#include <fstream>
#include <string>

#include "run_mtcs.h"

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
  const std::string in = MTCS_TEST_DATA "/access_maps/drilling_mcad_herringbone_gear_p04.txt";
  for (const std::string method : {"aica", "ica", "checkbox"}) {
    const fs::path out = scratch("am_" + method + ".txt");
    const auto r = run_mtcs("access-map --case " + in + " --mesh " MTCS_TEST_DATA "/meshes/mcad_herringbone_gear.off --out " +
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
