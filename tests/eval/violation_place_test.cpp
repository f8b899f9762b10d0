// Issue 16, item 6: every violation gives a real place, the closest points of what is too close
// (here their midpoint), checked against the closed forms of boxes and straight bores.

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "../support/scratch_file.h"
#include "mtcs/eval/pipeline.h"
#include "mtcs/mesh/mesh_io.h"

using namespace mtcs;
namespace fs = std::filesystem;

namespace {

fs::path write(const std::string& name, const std::string& text) {
  return mtcs_test::write_scratch("violation_place_test", name, text);
}

const std::string kRules = "drilling: {diameters: [8], allowed_faces: [+y, -y]}\n"
                           "circuits: {inlet_faces: [-y], outlet_faces: [+y]}\n"
                           "objectives: {use: [cost]}\n";

mold::Circuit straight(double x, double z, double y0 = 0, double y1 = 200) { return {{{x, y0, z}, {x, y1, z}}, 8}; }

// A copy: the evaluation is often a temporary.
eval::Violation only(const eval::Evaluation& e, const std::string& kind) {
  const eval::Violation* found = nullptr;
  for (const auto& v : e.violations)
    if (eval::to_string(v.kind) == kind) {
      REQUIRE_FALSE(found);
      found = &v;
    }
  REQUIRE(found);
  return *found;
}

}  // namespace

TEST_CASE("issue 16: an inlet or outlet off its faces is reported at the port, not at (0, 0, 0)", "[eval][issue16]") {
  const mold::Scene scene(mold::load_mold_spec(
      write("ports.yaml", "block: {box: {min: [0, 0, 0], max: [300, 200, 120]}}\n" + kRules).string()));
  const eval::Pipeline pipeline(scene);
  // Inlet 50 mm inside the -y face, outlet on +y.
  auto e = pipeline.evaluate(mold::Genome{{straight(100, 80, 50, 200)}});
  const auto in = only(e, "inlet_face");
  CHECK(in.distance == Approx(50));
  CHECK(in.where.isApprox(geometry::Vec3(100, 50, 80)));
  // Outlet 30 mm short of the +y face, inlet on -y.
  e = pipeline.evaluate(mold::Genome{{straight(120, 70, 0, 170)}});
  const auto out = only(e, "outlet_face");
  CHECK(out.distance == Approx(30));
  CHECK(out.where.isApprox(geometry::Vec3(120, 170, 70)));
  // The second circuit's port, not the first's.
  e = pipeline.evaluate(mold::Genome{{straight(60, 40), straight(200, 90, 0, 150)}});
  CHECK(only(e, "outlet_face").where.isApprox(geometry::Vec3(200, 150, 90)));
}

TEST_CASE("issue 16: a bore too close to a block face is reported midway between its wall and that face", "[eval][issue16]") {
  // Radius 4 with its axis at x = 6: 2 mm of steel to x = 0 along the whole bore; the place is
  // at x = 1 (between the wall at 2 and the face at 0), on the bore's height.
  const auto check = [](const std::string& block) {
    const mold::Scene scene(mold::load_mold_spec(
        write("surface.yaml", block + kRules + "clearances: {bore_surface: 5}\n").string()));
    const eval::Pipeline pipeline(scene);
    const auto v = only(pipeline.evaluate(mold::Genome{{straight(6, 60)}}), "bore_surface");
    CHECK(v.distance == Approx(2).margin(1e-9));
    CHECK(v.where.x() == Approx(1).margin(1e-9));
    CHECK(v.where.z() == Approx(60).margin(1e-9));
    CHECK(v.where.y() >= 0);
    CHECK(v.where.y() <= 200);
  };
  SECTION("box block") { check("block: {box: {min: [0, 0, 0], max: [300, 200, 120]}}\n"); }
  SECTION("mesh block") {
    const fs::path stl = write("block.stl", "");
    mesh::write_stl(stl.string(), mesh::box_mesh({{0, 0, 0}, {300, 200, 120}}));
    check("block: {mesh: " + stl.string() + "}\n");
  }
  // Near the top face instead: axis at z = 113, 3 mm of steel, the place at z = 118.5.
  const mold::Scene scene(mold::load_mold_spec(write(
      "top.yaml", "block: {box: {min: [0, 0, 0], max: [300, 200, 120]}}\n" + kRules + "clearances: {bore_surface: 5}\n")
                                                   .string()));
  const eval::Pipeline pipeline(scene);
  const auto v = only(pipeline.evaluate(mold::Genome{{straight(150, 113)}}), "bore_surface");
  CHECK(v.distance == Approx(3).margin(1e-9));
  CHECK(v.where.x() == Approx(150).margin(1e-9));
  CHECK(v.where.z() == Approx(118.5).margin(1e-9));
}

TEST_CASE("issue 16: a keep-out violation is reported between the bore and the keep-out, not at the bore's entry",
          "[eval][issue16]") {
  const fs::path stl = write("insert.stl", "");
  mesh::write_stl(stl.string(), mesh::box_mesh({{140, 90, 0}, {160, 110, 60}}));
  const mold::Scene scene(mold::load_mold_spec(
      write("keep_outs.yaml", "block: {box: {min: [0, 0, 0], max: [300, 200, 120]}}\n" + kRules +
                                  "keep_outs:\n"
                                  "  - {name: pin, cylinder: {p0: [50, 100, 0], p1: [50, 100, 100], radius: 3}, clearance: 5}\n"
                                  "  - {name: insert, mesh: " + stl.string() + ", clearance: 10}\n")
          .string()));
  const eval::Pipeline pipeline(scene);
  // Bore along y at x = 59, z = 80: its wall at x = 55, the pin's at 53: 2 mm, at (54, 100, 80).
  const auto pin = only(pipeline.evaluate(mold::Genome{{straight(59, 80)}}), "bore_keepout");
  CHECK(pin.elements == std::vector<std::string>{"c0.b0", "pin"});
  CHECK(pin.distance == Approx(2).margin(1e-9));
  CHECK(pin.where.isApprox(geometry::Vec3(54, 100, 80), 1e-9));
  // Bore along y over the insert at z = 70: its wall at 66, the insert's top at 60: 6 mm, the
  // place at z = 63 above the insert.
  const auto insert = only(pipeline.evaluate(mold::Genome{{straight(150, 70)}}), "bore_keepout");
  CHECK(insert.elements == std::vector<std::string>{"c0.b0", "insert"});
  CHECK(insert.distance == Approx(6).margin(1e-9));
  CHECK(insert.where.x() == Approx(150).margin(1e-9));
  CHECK(insert.where.z() == Approx(63).margin(1e-9));
  CHECK(insert.where.y() >= 90 - 1e-9);
  CHECK(insert.where.y() <= 110 + 1e-9);
}
