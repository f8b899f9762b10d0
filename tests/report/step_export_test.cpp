// STEP export read back with OpenCASCADE (the second translation unit that includes it): every
// bore of every bundled mold's reference layout is one named solid whose volume, radius and axis
// match the closed form of its hole (bores.csv of the same export: pi r^2 L, the segment p0-p1)
// within 1e-9 relative.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <numbers>
#include <vector>

#include <BRepAdaptor_Surface.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <Message.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include "cli/run_mtcs.h"
#include "support/paths.h"

namespace {

using mtcs_test::fs::path;

struct StepSolid {
  std::string name;
  int solids = 0, cylinders = 0, planes = 0;
  double volume = 0, radius = 0;
  gp_Ax1 axis;
  gp_Pnt centre;
};

std::vector<StepSolid> read_step(const path& file) {
  Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));  // quiet test output
  Handle(TDocStd_Document) doc;
  XCAFApp_Application::GetApplication()->NewDocument("MDTV-XCAF", doc);
  STEPCAFControl_Reader reader;
  reader.SetNameMode(Standard_True);
  REQUIRE(reader.ReadFile(file.c_str()) == IFSelect_RetDone);
  REQUIRE(reader.Transfer(doc));
  const Handle(XCAFDoc_ShapeTool) shapes = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  TDF_LabelSequence labels;
  shapes->GetFreeShapes(labels);
  std::vector<StepSolid> out;
  for (int i = 1; i <= labels.Length(); ++i) {
    StepSolid s;
    Handle(TDataStd_Name) name;
    if (labels(i).FindAttribute(TDataStd_Name::GetID(), name)) s.name = TCollection_AsciiString(name->Get()).ToCString();
    const TopoDS_Shape shape = shapes->GetShape(labels(i));
    for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next()) ++s.solids;
    GProp_GProps props;
    BRepGProp::VolumeProperties(shape, props, 1e-14);
    s.volume = props.Mass(), s.centre = props.CentreOfMass();
    for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
      const BRepAdaptor_Surface surface(TopoDS::Face(e.Current()));
      if (surface.GetType() == GeomAbs_Cylinder) ++s.cylinders, s.axis = surface.Cylinder().Axis(), s.radius = surface.Cylinder().Radius();
      if (surface.GetType() == GeomAbs_Plane) ++s.planes;
    }
    out.push_back(s);
  }
  return out;
}

std::vector<std::vector<std::string>> read_csv(const path& p) {
  std::vector<std::vector<std::string>> rows;
  std::istringstream in(mtcs_test::read_text(p));
  for (std::string line; std::getline(in, line);) {
    rows.emplace_back();
    std::istringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) rows.back().push_back(cell);
  }
  return rows;
}

}  // namespace

TEST_CASE("export step: every bore of every bundled reference layout read back exact to 1e-9", "[report][export][step]") {
  const path molds = path(MTCS_SOURCE_DIR) / "molds";
  int layouts = 0;
  for (const auto& entry : mtcs_test::fs::directory_iterator(molds)) {
    const std::string file = entry.path().filename().string();
    const std::string suffix = ".layout.yaml";
    if (file.size() <= suffix.size() || file.compare(file.size() - suffix.size(), suffix.size(), suffix) != 0) continue;
    const path spec = molds / (file.substr(0, file.size() - suffix.size()) + ".yaml");
    REQUIRE(mtcs_test::fs::exists(spec));
    SECTION(file) {
      const path step = mtcs_test::scratch("step", file + ".step"), csv = mtcs_test::scratch("step", file + ".csv");
      const std::string args = "export " + spec.string() + " --layout " + entry.path().string() + " --quiet";
      REQUIRE(mtcs_test::run_mtcs(args + " --format step --out " + step.string()) == 0);
      REQUIRE(mtcs_test::run_mtcs(args + " --format csv --out " + csv.string()) == 0);
      // The header names the writer, not OpenCASCADE's 'Unknown' (compared without whitespace:
      // the writer wraps its lines anywhere).
      const std::string text = mtcs_test::read_text(step);
      std::string header;
      for (const char c : text.substr(0, text.find("ENDSEC;")))
        if (!std::isspace(static_cast<unsigned char>(c))) header += c;
      CHECK_THAT(header, Catch::Contains("('mtcs')") && Catch::Contains("'mtcs0.1.0(OpenCASCADE)'"));
      CHECK_THAT(header, !Catch::Contains("'Unknown'"));
      const auto rows = read_csv(csv);  // name,circuit,segment,p0x,p0y,p0z,p1x,p1y,p1z,diameter,...
      const auto solids = read_step(step);
      REQUIRE(rows.size() > 1);
      REQUIRE(solids.size() == rows.size() - 1);
      for (std::size_t i = 0; i < solids.size(); ++i) {
        const auto& row = rows[i + 1];
        const StepSolid& s = solids[i];
        INFO(file << " bore " << row[0]);
        CHECK(s.name == row[0]);
        CHECK(s.solids == 1);
        CHECK(s.cylinders == 1);
        CHECK(s.planes == 2);
        const gp_Pnt p0(std::stod(row[3]), std::stod(row[4]), std::stod(row[5]));
        const gp_Pnt p1(std::stod(row[6]), std::stod(row[7]), std::stod(row[8]));
        const double r = std::stod(row[9]) / 2, length = p0.Distance(p1);
        const gp_Dir w(gp_Vec(p0, p1));
        CHECK(s.volume == Approx(std::numbers::pi * r * r * length).epsilon(1e-9).margin(0));
        CHECK(s.radius == Approx(r).epsilon(1e-9).margin(0));
        // The axis: parallel to p0-p1 (either sense), through p0, and the solid's centroid halfway.
        CHECK(gp_Vec(s.axis.Direction()).Crossed(gp_Vec(w)).Magnitude() <= 1e-9);
        CHECK(gp_Lin(s.axis).Distance(p0) <= 1e-9 * length);
        CHECK(s.centre.Distance(gp_Pnt((p0.XYZ() + p1.XYZ()) / 2)) <= 1e-9 * length);
      }
      ++layouts;
    }
  }
  CHECK(layouts >= 1);
}

TEST_CASE("export step: a baffle's and a bubbler's blind holes are solids named with their insert", "[report][export][step][baffle]") {
  const path dir = mtcs_test::scratch("step", "blind");
  mtcs_test::fs::create_directories(dir);
  std::string spec = mtcs_test::read_text(path(MTCS_SOURCE_DIR) / "molds" / "plate.yaml");
  const std::string faces = "  allowed_faces: [+x, -x, +y, -y]\n";
  REQUIRE(spec.find(faces) != std::string::npos);
  spec.replace(spec.find(faces), faces.size(), faces + "  baffles: {faces: [-z]}\n");
  std::ofstream(dir / "plate.yaml") << spec;
  std::ofstream(dir / "blind.layout.yaml")
      << "circuits:\n"
         "  - {diameter: 8, waypoints: [[70, 0, 88], [70, 150, 88], [100, 150, 88], [100, 0, 88]]}\n"
         "  - {diameter: 10, kind: bubbler, waypoints: [[117.5, 100, 0], [117.5, 100, 91]]}\n"
         "  - {diameter: 6, kind: baffle, waypoints: [[182.5, 100, 0], [182.5, 100, 91]]}\n";
  const std::string args = "export " + (dir / "plate.yaml").string() + " --layout " + (dir / "blind.layout.yaml").string() + " --quiet";
  REQUIRE(mtcs_test::run_mtcs(args + " --format step --out " + (dir / "blind.step").string()) == 0);
  const auto solids = read_step(dir / "blind.step");
  REQUIRE(solids.size() == 5);
  const double point = 0.5 / std::tan(59 * std::numbers::pi / 180);  // the drill point per mm of diameter
  for (const auto& [named, diameter] : {std::pair{std::string("c1.b0 bubbler"), 10.0}, std::pair{std::string("c2.b0 baffle"), 6.0}}) {
    // Copies: clang 14 cannot capture a structured binding in a lambda.
    const std::string name = named;
    const double d = diameter;
    INFO(name);
    const auto s = std::find_if(solids.begin(), solids.end(), [&](const StepSolid& x) { return x.name == name; });
    REQUIRE(s != solids.end());
    CHECK(s->radius == Approx(d / 2).epsilon(1e-9));
    // Up from the bottom face to the tip, and the drill's point past it (the export's coordinates
    // are the shop's, to 0.01 mm).
    const double length = std::round((91 + point * d) * 100) / 100;
    CHECK(s->volume == Approx(std::numbers::pi * d * d / 4 * length).epsilon(1e-9));
    CHECK(s->centre.Z() == Approx(length / 2).epsilon(1e-9));
  }
}
