// Issue 45, "STEP in": a part as the customer's CAD sends it. STEP (and IGES) files read by
// mesh::read_mesh through OpenCASCADE, checked against OpenCASCADE's own exact integration of the
// B-rep (BRepGProp: volume and area of the surfaces themselves, not of the tessellation): a
// part written by another tool (gmsh 4.8, docs/first-mold/lid.step), one written by OpenCASCADE
// through mtcs export, the same part as IGES; then a spec whose cavity is the STEP file, run as
// a designer would.

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <numbers>
#include <regex>

#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <IFSelect_ReturnStatus.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <Message.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Reader.hxx>
#include <TopoDS_Shape.hxx>

#include "cli/run_mtcs.h"
#include "mtcs/mesh/mesh_check.h"
#include "mtcs/mesh/mesh_io.h"
#include "support/paths.h"

namespace {

using mtcs_test::fs::path;

const path kLid = path(MTCS_SOURCE_DIR) / "docs/first-mold/lid.step";

TopoDS_Shape read_shape(const path& file) {
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
  STEPControl_Reader reader;
  REQUIRE(reader.ReadFile(file.c_str()) == IFSelect_RetDone);
  REQUIRE(reader.TransferRoots() > 0);
  return reader.OneShape();
}

// Volume and area of the B-rep, integrated on its exact surfaces.
std::pair<double, double> exact_volume_area(const TopoDS_Shape& shape) {
  GProp_GProps volume, area;
  BRepGProp::VolumeProperties(shape, volume, 1e-10);
  BRepGProp::SurfaceProperties(shape, area, 1e-10);
  return {volume.Mass(), area.Mass()};
}

// A mesh that bounds a solid (closed, outward, not self-intersecting) of the B-rep's volume and
// area. Every facet lies within the chordal tolerance s of its surface, so the volumes differ by
// at most s times the area; a facet's area falls short of its arc's by ~2s/(3r) relative (a
// polygon in a circle of radius r), 0.0033 on the lid's 2 mm hole.
void check_against_brep(const mtcs::mesh::TriangleMesh& m, const TopoDS_Shape& shape) {
  const mtcs::mesh::MeshCheck check = mtcs::mesh::check_mesh(m);
  INFO(check.message());
  CHECK(check.ok());
  const auto [volume, area] = exact_volume_area(shape);
  INFO("mesh " << m.signed_volume() << " mm^3, " << m.area() << " mm^2; B-rep " << volume << " mm^3, " << area << " mm^2");
  CHECK(std::abs(m.signed_volume() - volume) <= mtcs::mesh::kCadChordalTolerance * area);
  CHECK(m.area() == Approx(area).epsilon(2 * mtcs::mesh::kCadChordalTolerance / (3 * 2.0)));
}

}  // namespace

TEST_CASE("STEP in: a part written by gmsh reads as a closed, outward mesh of the B-rep's volume and area", "[mesh][step]") {
  REQUIRE(mtcs::mesh::reads_cad_files());
  const mtcs::mesh::TriangleMesh m = mtcs::mesh::read_mesh(kLid.string());
  check_against_brep(m, read_shape(kLid));
  // The lid of lid.geo: 80 x 50 x 20 mm from the origin, its planar faces exactly where drawn.
  const auto b = m.bounds();
  CHECK(b.min.norm() < 1e-9);
  CHECK((b.max - mtcs::geometry::Vec3(80, 50, 20)).norm() < 1e-9);
}

TEST_CASE("STEP in: the bores mtcs export writes (OpenCASCADE) read back as cylinders of pi r^2 L", "[mesh][step]") {
  const path dir = mtcs_test::scratch("step_import", "bore");
  mtcs_test::fs::create_directories(dir);
  std::ofstream(dir / "one.layout.yaml") << "circuits:\n  - diameter: 8\n    waypoints: [[70, 0, 24], [70, 115, 24]]\n";
  REQUIRE(mtcs_test::run_mtcs("export " + std::string(MTCS_SOURCE_DIR) + "/molds/cup.yaml --layout " +
                              (dir / "one.layout.yaml").string() + " --format step --out " + (dir / "one.step").string()) == 0);
  const mtcs::mesh::TriangleMesh m = mtcs::mesh::read_mesh((dir / "one.step").string());
  check_against_brep(m, read_shape(dir / "one.step"));
  // The bore as bores.csv has it: from y = 0 past the 115 mm waypoint by the drill's point.
  const auto b = m.bounds();
  CHECK(b.min.x() == Approx(66).margin(mtcs::mesh::kCadChordalTolerance));
  CHECK(b.max.x() == Approx(74).margin(mtcs::mesh::kCadChordalTolerance));
  const double length = b.max.y() - b.min.y();
  CHECK(std::abs(m.signed_volume() - std::numbers::pi * 16 * length) <= mtcs::mesh::kCadChordalTolerance * m.area());
}

TEST_CASE("IGES in: the same lid written as IGES reads to the same solid", "[mesh][step]") {
  const path file = mtcs_test::scratch("step_import", "lid.igs");
  const TopoDS_Shape shape = read_shape(kLid);
  IGESControl_Controller::Init();
  IGESControl_Writer writer("MM", 1);  // B-rep faces, as CAD systems write solids
  REQUIRE(writer.AddShape(shape));
  writer.ComputeModel();
  REQUIRE(writer.Write(file.c_str()));
  const mtcs::mesh::TriangleMesh m = mtcs::mesh::read_mesh(file.string());
  check_against_brep(m, shape);
}

TEST_CASE("STEP in: a spec whose cavity is a STEP part loads, is checked like any mesh and is scored", "[mesh][step][cli]") {
  const path dir = mtcs_test::scratch("step_import", "spec");
  mtcs_test::fs::create_directories(dir);
  const std::string spec =
      "units: mm\n"
      "block: {box: {min: [0, 0, 0], max: [140, 110, 60]}}\n"
      "cavity: {mesh: " + kLid.string() + ", translate: [30, 30, 30], sample_spacing: 4}\n"
      "drilling: {diameters: [8], axis_parallel: true, allowed_faces: [+x, -x, +y, -y]}\n"
      "clearances: {bore_bore: 4, bore_cavity: 1.0D, bore_surface: 3}\n"
      "circuits: {min: 1, max: 3, waypoints: [2, 8], inlet_faces: [-y], outlet_faces: [-y]}\n"
      "thermal: {coolant: {temperature: 40}, cavity_condition: coupled}\n"
      "objectives: {use: [temperature_std, cycle_time, cost]}\n";
  std::ofstream(dir / "lid.yaml") << spec;
  std::ofstream(dir / "lid.layout.yaml") << "circuits:\n  - diameter: 8\n    waypoints: [[45, 0, 40], [45, 100, 40], [95, 100, 40], [95, 0, 40]]\n";
  const path out = dir / "evaluate.json";
  REQUIRE(mtcs_test::run_mtcs("evaluate " + (dir / "lid.yaml").string() + " --layout " + (dir / "lid.layout.yaml").string() +
                              " --json > " + out.string()) == 0);
  const std::string json = mtcs_test::read_text(out);
  CHECK_THAT(json, Catch::Contains("\"cycle_time\""));
  // The loop runs through the lid's walls: the clearance check sees the STEP part.
  CHECK_THAT(json, Catch::Contains("\"bore_cavity\""));
  // A file that is not STEP: exit 2, the file named.
  std::ofstream(dir / "broken.step") << "ISO-10303-21;\nHEADER;\nthis is not STEP\n";
  std::ofstream(dir / "broken.yaml") << std::regex_replace(spec, std::regex(kLid.string()), (dir / "broken.step").string());
  const mtcs_test::Run broken = mtcs_test::run_mtcs_err(
      "step_import", "evaluate " + (dir / "broken.yaml").string() + " --layout " + (dir / "lid.layout.yaml").string());
  CHECK(broken.code == 2);
  CHECK_THAT(broken.err, Catch::Contains((dir / "broken.step").string()));
}
