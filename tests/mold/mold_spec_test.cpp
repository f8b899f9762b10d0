// The mold spec reader: every bad input gets one InputError naming the file, the line and column
// and the field's path.

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>

#include <unistd.h>

#include "../support/scratch_file.h"
#include "mtcs/io/input_error.h"
#include "mtcs/mold/mold_spec.h"
#include "support/thrown_by.h"
#include "support/paths.h"

using namespace mtcs;
namespace fs = std::filesystem;

namespace {

fs::path write(const std::string& name, const std::string& text) {
  return mtcs_test::write_scratch("mold_spec_test", name, text);
}

const std::string kBlock = "block: {box: {min: [0, 0, 0], max: [100, 100, 50]}}\n";

// Loads the spec and returns the error it raises.
io::InputError error_of(const std::string& text, const std::string& name = "spec.yaml") {
  const auto p = write(name, text);
  return mtcs_test::thrown_by<io::InputError>([&] { mold::load_mold_spec(p.string()); }, text);
}

}  // namespace

TEST_CASE("mold spec: the bundled plate loads with its defaults", "[mold]") {
  const auto spec = mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/plate.yaml");
  CHECK(spec.block.box->max.x() == 300);
  CHECK(spec.cavity->box);
  CHECK(spec.keep_outs.size() == 4);
  CHECK(spec.clearances.bore_cavity.per_diameter);
  CHECK(spec.clearances.bore_cavity.at(8) == 8);
  CHECK(spec.objectives.use.size() == 3);
  // Issue 11: the bundled molds score temperatures, with a thermal section of their own; issue
  // 40: the part coupled to the steel, the cycle time among the objectives.
  CHECK(mold::is_temperature_objective(spec.objectives.use[0]));
  CHECK(spec.thermal.cavity_condition == mold::CavityCondition::Coupled);
  CHECK_FALSE(spec.thermal.heat_flux);
  CHECK(spec.objectives.use[1] == mold::Objective::CycleTime);
}

TEST_CASE("mold spec: bad input names file, line, column and field", "[mold][errors]") {
  SECTION("unknown key") {
    const auto e = error_of(kBlock + "drilling:\n  diameter: [8]\n");
    CHECK(e.line() == 3);
    CHECK(e.column() == 3);
    CHECK(e.field() == "drilling.diameter");
    CHECK(std::string(e.what()).find("unknown key") != std::string::npos);
    // A typo names the key it most likely meant, then the list.
    CHECK_THAT(e.what(), Catch::Contains("did you mean 'diameters'? (expected one of: "));
  }
  SECTION("unknown key: a swap, a missing letter; nothing near, or two equally near, names none") {
    CHECK_THAT(error_of(kBlock + "cirucits: {min: 1}\n").what(), Catch::Contains("did you mean 'circuits'?"));
    CHECK_THAT(error_of(kBlock + "clearances: {bore_bor: 4}\n").what(), Catch::Contains("did you mean 'bore_bore'?"));
    CHECK_THAT(error_of(kBlock + "colour: red\n").what(), !Catch::Contains("did you mean"));
    CHECK_THAT(error_of(kBlock + "colour: red\n").what(), Catch::Contains("unknown key; expected one of: "));
    // "mix" is one edit from both "min" and "max": no guess.
    CHECK_THAT(error_of(kBlock + "circuits: {mix: 3}\n").what(), !Catch::Contains("did you mean"));
  }
  SECTION("duplicate key") {
    const auto e = error_of(kBlock + "clearances:\n  bore_bore: 4\n  bore_bore: 5\n");
    CHECK(e.line() == 4);
    CHECK(e.field() == "clearances.bore_bore");
    CHECK(std::string(e.what()).find("duplicate") != std::string::npos);
  }
  SECTION("wrong type") {
    const auto e = error_of(kBlock + "drilling: {axis_parallel: maybe}\n");
    CHECK(e.line() == 2);
    CHECK(e.column() == 27);
    CHECK(e.field() == "drilling.axis_parallel");
  }
  SECTION("out of range") {
    const auto e = error_of(kBlock + "drilling:\n  diameters: [8, -2]\n");
    CHECK(e.line() == 3);
    CHECK(e.column() == 18);
    CHECK(e.field() == "drilling.diameters[1]");
    CHECK(std::string(e.what()).find("out of range") != std::string::npos);
  }
  SECTION("a face that is not one") {
    CHECK(error_of(kBlock + "circuits: {inlet_faces: [top]}\n").field() == "circuits.inlet_faces[0]");
  }
  SECTION("a parting the part cannot have") {
    const std::string cup = "cavity:\n  box: {min: [10, 10, 10], max: [90, 90, 40]}\n";
    CHECK(error_of(kBlock + cup + "  parting: {core: +z}\n").field() == "cavity.parting.at");
    CHECK(error_of(kBlock + cup + "  parting: {at: 40}\n").field() == "cavity.parting.core");
    CHECK(error_of(kBlock + cup + "  parting: {core: up, at: 40}\n").field() == "cavity.parting.core");
    const auto outside = error_of(kBlock + cup + "  parting: {core: +z, at: 60}\n");  // the block ends at z = 50
    CHECK(outside.field() == "cavity.parting.at");
    CHECK(outside.line() == 4);
    const auto patch = error_of(kBlock + "cavity:\n  patch: {face: +z, min: [10, 10], max: [90, 90]}\n  parting: {core: +z, at: 50}\n");
    CHECK(patch.field() == "cavity.parting");
    const auto unparted = error_of(kBlock + cup + "objectives: {use: [temperature_std_side, cost]}\n");
    CHECK(unparted.field() == "objectives.use[0]");
    CHECK_THAT(unparted.what(), Catch::Contains("cavity.parting"));
  }
  SECTION("a bad per-diameter length") {
    CHECK(error_of(kBlock + "clearances: {bore_cavity: 2xD}\n").field() == "clearances.bore_cavity");
  }
  SECTION("missing block") {
    CHECK(error_of("units: mm\n").field() == "block");
  }
  SECTION("YAML syntax") {
    const auto e = error_of(kBlock + "drilling: [1, 2\n");
    CHECK(e.line() >= 2);
  }
  SECTION("missing mesh file") {
    const auto e = error_of(kBlock + "cavity: {mesh: nowhere.stl}\n");
    CHECK(e.field() == "cavity.mesh");
    CHECK(e.line() == 2);
    CHECK(std::string(e.what()).find("not found") != std::string::npos);
  }
  SECTION("a mesh that is not closed") {
    write("open.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n");
    const auto e = error_of(kBlock + "cavity: {mesh: open.off}\n");
    CHECK(e.field() == "cavity.mesh");
    CHECK(std::string(e.what()).find("not closed") != std::string::npos);
  }
  SECTION("a mesh with a degenerate triangle") {
    write("degenerate.off", "OFF\n4 5 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n3 0 1 1\n");
    const auto e = error_of(kBlock + "keep_outs:\n  - {name: insert, mesh: degenerate.off}\n");
    CHECK(e.field() == "keep_outs[0].mesh");
    CHECK(std::string(e.what()).find("degenerate") != std::string::npos);
  }
  SECTION("a mesh with a non-finite vertex") {
    write("nan.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 nan\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
    const auto e = error_of(kBlock + "cavity: {mesh: nan.off}\n");
    CHECK(e.field() == "cavity.mesh");
  }
  SECTION("a mesh oriented inwards") {
    write("inward.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 3 1\n3 0 2 3\n3 1 3 2\n");
    CHECK(std::string(error_of(kBlock + "cavity: {mesh: inward.off}\n").what()).find("inwards") != std::string::npos);
  }
}

TEST_CASE("mold spec: a closed tetrahedron loads and is translated", "[mold]") {
  write("tet.off", "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  const auto p = write("tet.yaml", kBlock + "cavity: {mesh: tet.off, translate: [10, 20, 30], sample_spacing: 0.5}\n");
  const auto spec = mold::load_mold_spec(p.string());
  REQUIRE(spec.cavity->mesh);
  CHECK(spec.cavity->mesh->mesh.bounds().min == geometry::Vec3(10, 20, 30));
  CHECK(spec.cavity->mesh->mesh.signed_volume() == Approx(1.0 / 6));
}

TEST_CASE("issue 16: without circuits.min a part gets one circuit per 40 mm of its longest side (the ES stopped at 2)",
          "[mold][issue16]") {
  // The first-mold part: 96.6 x 104.9 x 53.6 mm, ceil(104.9 / 40) = 3 circuits at least, of 4.
  const mold::MoldSpec part = mold::load_mold_spec(MTCS_SOURCE_DIR + "/docs/first-mold/part.yaml");
  CHECK(part.circuits.min == 3);
  CHECK(part.circuits.max == 4);
  auto limits = [](const std::string& cavity, const std::string& circuits) {
    const std::string block = "block: {box: {min: [0, 0, 0], max: [300, 300, 100]}}\n";
    return mold::load_mold_spec(write("c.yaml", block + cavity + circuits).string()).circuits;
  };
  // 40 mm or less: 1; 40.5 mm: 2; 200 mm: capped at 3; a max below that caps it.
  CHECK(limits("cavity: {box: {min: [100, 100, 40], max: [140, 110, 50]}}\n", "").min == 1);
  CHECK(limits("cavity: {box: {min: [100, 100, 40], max: [140.5, 110, 50]}}\n", "").min == 2);
  CHECK(limits("cavity: {box: {min: [50, 50, 40], max: [250, 110, 50]}}\n", "").min == 3);
  CHECK(limits("cavity: {box: {min: [50, 50, 40], max: [250, 110, 50]}}\n", "circuits: {max: 2}\n").min == 2);
  // What the spec says is kept, and the bundled molds say it.
  CHECK(limits("cavity: {box: {min: [50, 50, 40], max: [250, 110, 50]}}\n", "circuits: {min: 1}\n").min == 1);
  CHECK(mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml").circuits.min == 1);
}

// Fuzz crash #16 (mold_spec, crash-b9a2fcf4): a mesh path with a name longer than the file system
// allows made std::filesystem::exists throw filesystem_error ("File name too long"), which ended
// the process instead of an InputError at the field.
TEST_CASE("mold spec defect: a mesh name too long for the file system is an error at its field", "[mold][fuzz-defect]") {
  const auto e = error_of(kBlock + "cavity:\n  mesh: " + std::string(300, 'b') + ".off\n");
  CHECK(e.field() == "cavity.mesh");
  CHECK(e.line() == 3);
  CHECK_THAT(std::string(e.what()), Catch::Contains("mesh file not found") && Catch::Contains("too long"));
}
