// Baffles and bubblers (issue 42, item 5): a blind hole drilled along a face's normal, written
// in a layout as `kind: baffle` (or bubbler) with its entry and tip, decoded as one bore whose
// coolant goes down and back, refused with the field when it cannot be drilled as written.

#include <catch2/catch.hpp>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "mtcs/io/input_error.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "support/bundled_variant.h"
#include "support/paths.h"
#include "support/scratch_file.h"
#include "support/thrown_by.h"

using namespace mtcs;

namespace {

// The plate, blind holes allowed up from its bottom face (-z) toward the cavity at z = 105.
const mold::MoldSpec& plate_with_baffles() {
  static const mold::MoldSpec spec = mold::load_mold_spec(mtcs_test::bundled_variant(
      "plate", "  allowed_faces: [+x, -x, +y, -y]\n", "  allowed_faces: [+x, -x, +y, -y]\n  baffles: {faces: [-z], max: 2}\n"));
  return spec;
}

std::string write(const std::string& name, const std::string& text) {
  return mtcs_test::write_scratch("blind_bore_test", name, text).string();
}

std::string blind(const std::string& kind, const std::string& waypoints, const std::string& diameter = "10") {
  return "circuits:\n  - diameter: " + diameter + "\n    kind: " + kind + "\n    waypoints: " + waypoints + "\n";
}

io::InputError error_of(const std::string& name, const std::string& text, const mold::MoldSpec& spec) {
  const std::string path = write(name, text);
  return mtcs_test::thrown_by<io::InputError>([&] { mold::read_layout(path, spec); }, text);
}

// The drill point's length beyond the tip: 0.5 D cot(118 deg / 2).
double point(double d) { return 0.5 * d / std::tan(59 * std::numbers::pi / 180); }

}  // namespace

TEST_CASE("blind bore: a baffle decodes to one hole up from its face, the drill point past its tip", "[mold][baffle]") {
  const mold::Scene scene(plate_with_baffles());
  const auto w = mold::read_layout(write("baffle.layout.yaml", blind("baffle", "[[100, 100, 0], [100, 100, 80]]")),
                                   scene.spec());
  REQUIRE(w.genome.circuits.size() == 1);
  CHECK(w.genome.circuits[0].kind == mold::CircuitKind::Baffle);
  const mold::Layout layout = mold::decode(scene, w.genome);
  REQUIRE(layout.bores.size() == 1);
  const mold::Bore& b = layout.bores[0];
  CHECK(b.kind == mold::CircuitKind::Baffle);
  CHECK(b.hole.p0 == geometry::Vec3(100, 100, 0));
  CHECK(b.hole.p1.x() == 100);
  CHECK(b.hole.p1.z() == Approx(80 + point(10)).epsilon(1e-12));
  CHECK(b.flow_start == geometry::Vec3(100, 100, 0));
  CHECK(b.flow_end == geometry::Vec3(100, 100, 80));
  CHECK(b.entry_face == mold::Face::NegZ);
  CHECK(b.entry_allowed);
  CHECK_FALSE(b.plugged);
  CHECK_FALSE(b.through);
  CHECK(b.drilled_length == Approx(80 + point(10)).epsilon(1e-12));
  CHECK(b.tube_outer == 0);
  CHECK(layout.ports.empty());  // both ports at the entry, on an allowed face
  CHECK(layout.plugs == 0);
  CHECK(layout.junctions.empty());
}

TEST_CASE("blind bore: the optimiser's waypoints are put on the drilled axis", "[mold][baffle]") {
  const mold::Scene scene(plate_with_baffles());
  const auto axis = [&](geometry::Vec3 entry, geometry::Vec3 tip, double d = 8) {
    return mold::blind_axis(scene, mold::Circuit{{entry, tip}, d, mold::CircuitKind::Bubbler});
  };
  // Off the face and leaning: the entry onto the face, the tip straight above it.
  mold::BlindAxis a = axis({100, 90, 3}, {104, 95, 60});
  CHECK(a.face == mold::Face::NegZ);
  CHECK(a.entry == geometry::Vec3(100, 90, 0));
  CHECK(a.tip == geometry::Vec3(100, 90, 60));
  // Outside the block, or too shallow: at least a diameter deep.
  a = axis({100, 90, -4}, {100, 90, -10});
  CHECK(a.tip == geometry::Vec3(100, 90, 8));
  // Through the block: the drill point stays inside.
  a = axis({100, 90, 0}, {100, 90, 500});
  CHECK(a.tip.z() + point(8) == Approx(120).margin(1e-3));
  CHECK(a.tip.z() + point(8) < 120);
  // A bubbler carries the spec's tube (0.7 and 0.55 of the bore by default).
  const mold::Layout layout =
      mold::decode(scene, mold::Genome{{mold::Circuit{{{100, 90, 0}, {100, 90, 60}}, 8, mold::CircuitKind::Bubbler}}});
  REQUIRE(layout.bores.size() == 1);
  CHECK(layout.bores[0].tube_outer == Approx(5.6));
  CHECK(layout.bores[0].tube_inner == Approx(4.4));
}

TEST_CASE("blind bore: kinds are written and read back, and holes.csv and bores.csv name the insert", "[mold][baffle]") {
  const mold::Scene scene(plate_with_baffles());
  mold::Genome g;
  g.circuits.push_back({{{70, 0, 60}, {70, 150, 60}, {100, 150, 60}, {100, 0, 60}}, 8});
  g.circuits.push_back({{{150, 100, 0}, {150, 100, 90}}, 10, mold::CircuitKind::Bubbler});
  g.circuits.push_back({{{200, 100, 0}, {200, 100, 85.5}}, 6, mold::CircuitKind::Baffle});
  const std::string path = write("kinds.layout.yaml", "");
  mold::save_layout(path, g);
  const mold::Genome back = mold::load_layout(path, scene.spec());
  REQUIRE(back.circuits.size() == 3);
  for (std::size_t c = 0; c < 3; ++c) {
    CHECK(back.circuits[c].kind == g.circuits[c].kind);
    CHECK(back.circuits[c].diameter == g.circuits[c].diameter);
    CHECK(back.circuits[c].waypoints == g.circuits[c].waypoints);
  }
  const std::string holes = write("holes.csv", "");
  mold::save_holes_csv(holes, mold::decode(scene, back));
  std::ifstream in(holes);
  std::stringstream text;
  text << in.rdbuf();
  CHECK_THAT(text.str(), Catch::StartsWith("hole,circuit,entry_x,entry_y,entry_z,direction_x,direction_y,direction_z,"
                                           "diameter,depth,entry_face,plug_x,plug_y,plug_z,insert\n"));
  CHECK_THAT(text.str(), Catch::Contains("\nc1.b0,1,150,100,0,0,0,1,10,"));
  CHECK_THAT(text.str(), Catch::Contains(",-z,,,,bubbler\n"));
  CHECK_THAT(text.str(), Catch::Contains(",-z,,,,baffle\n"));
  CHECK_THAT(text.str(), Catch::Contains("\nc0.b0,0,70,0,60,0,1,0,8,"));
  // bores.csv names it too (what mtcs clearance --cylinders reads; it takes columns by name).
  const std::string bores = write("bores.csv", "");
  mold::save_bores_csv(bores, mold::decode(scene, back));
  std::ifstream bin(bores);
  std::stringstream btext;
  btext << bin.rdbuf();
  CHECK_THAT(btext.str(), Catch::StartsWith("name,circuit,segment,p0x,p0y,p0z,p1x,p1y,p1z,diameter,entry_face,plugged,dead_end,insert\n"));
  CHECK_THAT(btext.str(), Catch::Contains(",-z,0,0,bubbler\n") && Catch::Contains(",-z,0,0,baffle\n"));
}

TEST_CASE("blind bore: a layout's baffle that cannot be drilled as written is refused at its field", "[mold][baffle]") {
  const mold::MoldSpec& spec = plate_with_baffles();
  io::InputError e = error_of("typo.layout.yaml", blind("baffel", "[[100, 100, 0], [100, 100, 80]]"), spec);
  CHECK(e.field() == "circuits[0].kind");
  CHECK(e.line() == 3);
  CHECK_THAT(std::string(e.what()), Catch::Contains("unknown kind 'baffel': expected drilled, baffle or bubbler"));

  e = error_of("three.layout.yaml", blind("baffle", "[[100, 100, 0], [100, 100, 40], [100, 100, 80]]"), spec);
  CHECK(e.field() == "circuits[0].waypoints");
  CHECK_THAT(std::string(e.what()), Catch::Contains("is one blind hole: give two waypoints"));

  e = error_of("off_face.layout.yaml", blind("bubbler", "[[100, 100, 2], [100, 100, 80]]"), spec);
  CHECK(e.field() == "circuits[0].waypoints[0]");
  CHECK_THAT(std::string(e.what()), Catch::Contains("is on none of drilling.baffles.faces (-z)"));

  e = error_of("leaning.layout.yaml", blind("bubbler", "[[100, 100, 0], [100.02, 100, 80]]"), spec);
  CHECK(e.field() == "circuits[0].waypoints[1]");
  CHECK_THAT(std::string(e.what()), Catch::Contains("is not straight below the entry"));

  e = error_of("shallow.layout.yaml", blind("baffle", "[[100, 100, 0], [100, 100, 6]]", "8"), spec);
  CHECK(e.field() == "circuits[0].waypoints[1]");
  CHECK_THAT(std::string(e.what()), Catch::Contains("the tip is 6 mm into the block; at least a diameter (8 mm)"));

  e = error_of("outside.layout.yaml", blind("baffle", "[[100, 100, 0], [100, 100, 130]]"), spec);
  CHECK_THAT(std::string(e.what()), Catch::Contains("is outside the block"));

  // 118 of the block's 120 mm: the drill's point (3 mm for 10 mm) would come out of the top face.
  e = error_of("point_out.layout.yaml", blind("baffle", "[[100, 100, 0], [100, 100, 118]]"), spec);
  CHECK(e.field() == "circuits[0].waypoints[1]");
  CHECK_THAT(std::string(e.what()), Catch::Contains("the drill's point (3.004303 mm past the tip) would leave the block's far face, 2 mm"));

  // A diameter deep within the shop's rounding (what a saved layout holds) is read.
  CHECK(mold::read_layout(write("one_d.layout.yaml", blind("baffle", "[[100, 100, 0], [100, 100, 7.995]]", "8")), spec)
            .genome.circuits.size() == 1);

  // A kind the spec's drilling.baffles.kinds leaves out.
  const mold::MoldSpec baffles_only = mold::load_mold_spec(mtcs_test::bundled_variant(
      "plate", "  allowed_faces: [+x, -x, +y, -y]\n", "  allowed_faces: [+x, -x, +y, -y]\n  baffles: {faces: [-z], kinds: [baffle]}\n"));
  e = error_of("kind_not_listed.layout.yaml", blind("bubbler", "[[100, 100, 0], [100, 100, 80]]"), baffles_only);
  CHECK(e.field() == "circuits[0].kind");
  CHECK_THAT(std::string(e.what()), Catch::Contains("drilling.baffles.kinds of the mold spec does not list bubbler"));

  // A spec without drilling.baffles takes none.
  const mold::MoldSpec plain = mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/plate.yaml");
  e = error_of("unallowed.layout.yaml", blind("baffle", "[[100, 100, 0], [100, 100, 80]]"), plain);
  CHECK(e.field() == "circuits[0].kind");
  CHECK_THAT(std::string(e.what()), Catch::Contains("the mold spec allows no baffles or bubblers; add drilling.baffles"));
}

TEST_CASE("blind bore: drilling.baffles is read with its defaults and refused when wrong", "[mold][baffle][spec]") {
  const mold::BaffleSpec& b = *plate_with_baffles().drilling.baffles;
  CHECK(b.faces == std::vector<mold::Face>{mold::Face::NegZ});
  CHECK(b.max == 2);
  CHECK(b.kinds.size() == 2);
  CHECK(b.tube_outer == 0.7);
  CHECK(b.tube_inner == 0.55);
  const mold::MoldSpec all = mold::load_mold_spec(mtcs_test::bundled_variant(
      "plate", "  allowed_faces: [+x, -x, +y, -y]\n", "  allowed_faces: [+x, -x, +y, -y]\n  baffles: true\n"));
  CHECK(all.drilling.baffles->faces == std::vector<mold::Face>{mold::Face::PosZ});
  const auto refused = [](const std::string& line) {
    const std::string path = mtcs_test::bundled_variant("plate", "  allowed_faces: [+x, -x, +y, -y]\n",
                                                        "  allowed_faces: [+x, -x, +y, -y]\n  baffles: " + line + "\n");
    return mtcs_test::thrown_by<io::InputError>([&] { mold::load_mold_spec(path); }, line);
  };
  CHECK(refused("{kinds: [blade]}").field() == "drilling.baffles.kinds[0]");
  CHECK(refused("{kinds: [drilled]}").field() == "drilling.baffles.kinds[0]");
  CHECK(refused("{tube: [0.5, 0.6]}").field() == "drilling.baffles.tube[1]");
  CHECK(refused("{tube: 0.7}").field() == "drilling.baffles.tube");
  CHECK(refused("{faces: [+q]}").field().rfind("drilling.baffles.faces", 0) == 0);
  CHECK(refused("{depth: 3}").field() == "drilling.baffles.depth");
}
