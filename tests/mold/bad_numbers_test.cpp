// Bad numbers where a mold spec enters (issue 15, item 5): NaN, infinities, numbers beyond
// double, 1e308 coordinates, denormals, negative zero, a cavity sampled into billions of
// points, 0-area and duplicated triangles, 10 000 keep-outs. Each gives a clear error naming
// the field or the correct result; none crashes or hangs.

#include <catch2/catch.hpp>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "../support/scratch_file.h"
#include "mtcs/io/input_error.h"
#include "mtcs/mold/mold_spec.h"
#include "mtcs/mold/scene.h"
#include "support/thrown_by.h"

using namespace mtcs;
namespace fs = std::filesystem;

namespace {

fs::path write(const std::string& name, const std::string& text) {
  return mtcs_test::write_scratch("bad_numbers_test", name, text);
}

const std::string kBlock = "block: {box: {min: [0, 0, 0], max: [100, 100, 50]}}\n";

io::InputError error_of(const std::string& text) {
  return mtcs_test::thrown_by<io::InputError>([&] { mold::load_mold_spec(write("spec.yaml", text).string()); }, text);
}

mold::MoldSpec load(const std::string& text) { return mold::load_mold_spec(write("spec.yaml", text).string()); }

const std::string kTetra = "OFF\n4 4 0\n0 0 0\n10 0 0\n0 10 0\n0 0 10\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

}  // namespace

TEST_CASE("bad numbers: NaN, infinities and numbers beyond double are refused at their place", "[mold][bad-numbers]") {
  for (const std::string v : {".nan", "nan", ".NaN", ".inf", "-.inf", "inf", "1e309", "-1e400", "0x10", "1e", "--1"}) {
    INFO(v);
    const auto e = error_of(kBlock + "drilling:\n  diameters: [8, " + v + "]\n");
    CHECK(e.line() == 3);
    CHECK(e.column() == 18);
    CHECK(e.field() == "drilling.diameters[1]");
  }
  const auto e = error_of("block: {box: {min: [0, 0, .nan], max: [100, 100, 50]}}\n");
  CHECK(e.field() == "block.box.min[2]");
  CHECK(e.column() == 27);
}

TEST_CASE("bad numbers: a coordinate of 1e308 is out of range, not an infinity later", "[mold][bad-numbers]") {
  const auto e = error_of("block: {box: {min: [-1e308, 0, 0], max: [1e308, 100, 50]}}\n");
  CHECK(e.field() == "block.box.min[0]");
  CHECK_THAT(std::string(e.what()), Catch::Contains("out of range"));
  CHECK(error_of(kBlock + "keep_outs:\n  - {name: k, cylinder: {p0: [1, 1, 0], p1: [1, 1, 1.7e308], radius: 1}}\n").field() ==
        "keep_outs[0].cylinder.p1[2]");
  // The bound is a kilometre scale, far beyond any mold: 1e6 mm still loads (a block of a
  // plausible size there: the scene check refuses blocks over 10 m, scene_check_test.cpp).
  CHECK(load("block: {box: {min: [-1e6, 0, 0], max: [-999900, 100, 50]}}\n").block.box->min.x() == -1e6);
}

TEST_CASE("bad numbers: denormals and negative zero are numbers like any other", "[mold][bad-numbers]") {
  const auto spec = load(kBlock + "clearances: {bore_bore: 4.9e-324, bore_surface: -0}\n");
  CHECK(spec.clearances.bore_bore == 4.9e-324);  // the smallest denormal, read exactly
  CHECK(spec.clearances.bore_surface == 0.0);
  // -0 is 0: where 0 is out of range, so is -0.
  CHECK(error_of(kBlock + "drilling: {diameters: [-0]}\n").field() == "drilling.diameters[0]");
  const auto b = load("block: {box: {min: [-0, -0.0, 0], max: [100, 100, 50]}}\n").block.box;
  CHECK(b->min == geometry::Vec3(0, 0, 0));
}

TEST_CASE("bad numbers: a cavity sampled into more than 2e7 points asks for a larger spacing", "[mold][bad-numbers]") {
  const auto t0 = std::chrono::steady_clock::now();
  // A 10 m block, the largest the scene check accepts (scene_check_test.cpp).
  const std::string block = "block: {box: {min: [0, 0, 0], max: [1e4, 1e4, 1e4]}}\n";
  auto e = error_of(block + "cavity: {box: {min: [10, 10, 10], max: [9e3, 9e3, 9e3]}, sample_spacing: 0.001}\n");
  CHECK(e.field() == "cavity.sample_spacing");
  CHECK_THAT(std::string(e.what()), Catch::Contains("raise sample_spacing"));
  // Without a spacing, the default 3 mm on a 9 m box is too fine as well: the cavity is named.
  e = error_of(block + "cavity: {box: {min: [10, 10, 10], max: [9e3, 9e3, 9e3]}}\n");
  CHECK(e.field() == "cavity");
  // A patch and a mesh are counted too.
  CHECK(error_of(block + "cavity: {patch: {face: +z, min: [0, 0], max: [1e4, 1e4]}, sample_spacing: 0.01}\n").field() ==
        "cavity.sample_spacing");
  write("tetra.off", kTetra);
  CHECK(error_of(kBlock + "cavity: {mesh: tetra.off, sample_spacing: 0.001}\n").field() == "cavity.sample_spacing");
  CHECK(std::chrono::steady_clock::now() - t0 < std::chrono::seconds(5));  // refused before sampling
  // At the bundled spacing the same shapes load.
  CHECK(load(kBlock + "cavity: {mesh: tetra.off, sample_spacing: 0.5}\n").cavity->mesh);
}

TEST_CASE("bad numbers: 0-area and duplicated triangles in a mesh are refused by name", "[mold][bad-numbers]") {
  // A tetrahedron with one triangle twice: four triangles on an edge.
  write("twice.off", "OFF\n4 5 0\n0 0 0\n10 0 0\n0 10 0\n0 0 10\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n3 1 2 3\n");
  auto e = error_of(kBlock + "cavity: {mesh: twice.off}\n");
  CHECK(e.field() == "cavity.mesh");
  CHECK_THAT(std::string(e.what()), Catch::Contains("more than two triangles"));
  // Three distinct corners on a line: zero area without a repeated index.
  write("flat.off", "OFF\n5 5 0\n0 0 0\n10 0 0\n0 10 0\n0 0 10\n5 0 0\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n3 0 4 1\n");
  e = error_of(kBlock + "cavity: {mesh: flat.off}\n");
  CHECK_THAT(std::string(e.what()), Catch::Contains("degenerate (zero area)"));
  // A tetrahedron of 1e-50 mm loads (positive volume); at 1e-100 mm its edges' cross products
  // underflow (1e-200 squared): refused as zero area, not a division by zero later.
  const std::string tiny = "OFF\n4 4 0\n0 0 0\nS 0 0\n0 S 0\n0 0 S\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  const auto sized = [&](const std::string& s) {
    std::string t = tiny;
    for (std::size_t at; (at = t.find('S')) != std::string::npos;) t.replace(at, 1, s);
    return t;
  };
  write("tiny.off", sized("1e-50"));
  const auto spec = load(kBlock + "keep_outs:\n  - {name: speck, mesh: tiny.off}\n");
  CHECK(spec.keep_outs[0].mesh->mesh.signed_volume() > 0);
  write("tinier.off", sized("1e-100"));
  CHECK_THAT(std::string(error_of(kBlock + "keep_outs:\n  - {name: speck, mesh: tinier.off}\n").what()),
             Catch::Contains("degenerate (zero area)"));
}

TEST_CASE("bad numbers: a mold spec with 10 000 keep-outs loads and builds its scene", "[mold][bad-numbers]") {
  std::ostringstream spec;
  spec << "block: {box: {min: [0, 0, 0], max: [1000, 1000, 100]}}\n"
       << "cavity: {box: {min: [100, 100, 90], max: [900, 900, 95]}, sample_spacing: 20}\n"
       << "keep_outs:\n";
  for (int i = 0; i < 10000; ++i)
    spec << "  - {name: pin" << i << ", cylinder: {p0: [" << 5 + (i % 100) * 9.9 << ", " << 5 + (i / 100) * 9.9
         << ", 0], p1: [" << 5 + (i % 100) * 9.9 << ", " << 5 + (i / 100) * 9.9 << ", 89], radius: 1}, clearance: 1}\n";
  const auto t0 = std::chrono::steady_clock::now();
  mold::MoldSpec s = load(spec.str());
  REQUIRE(s.keep_outs.size() == 10000);
  CHECK(s.keep_outs[9999].name == "pin9999");
  CHECK(s.keep_outs[9999].cylinder->p0.x() == Approx(5 + 99 * 9.9));
  const mold::Scene scene(std::move(s));
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  INFO("10 000 keep-outs: load + scene " << seconds << " s");
  CHECK(seconds < 20);  // linear work; a quadratic check would take minutes
}
