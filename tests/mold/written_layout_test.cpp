// A user's layout is scored as written or refused (issue 16, item 1): the decoder used to replace
// a waypoint's coordinate along an axis no allowed face is drilled along by the inlet's, so a
// circuit stepping from z = 35 to z = 85 scored exactly like the flat one.

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "../support/scratch_file.h"
#include "mtcs/eval/pipeline.h"
#include "mtcs/io/input_error.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/run/shop_layout.h"
#include "support/thrown_by.h"
#include "support/paths.h"

using namespace mtcs;
namespace fs = std::filesystem;

namespace {

const std::string kMold = MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml";

fs::path write(const std::string& name, const std::string& text) {
  return mtcs_test::write_scratch("written_layout_test", name, text);
}

// One U loop from the -y face: inlet at z = 35, a step up to `far_z`, the rest at `far_z`.
std::string u_loop(const std::string& far_z) {
  return "circuits:\n"
         "  - diameter: 8\n"
         "    waypoints:\n"
         "      - [70, 0, 35]\n"
         "      - [70, 150, 35]\n"
         "      - [70, 150, " + far_z + "]\n"
         "      - [100, 150, " + far_z + "]\n"
         "      - [100, 0, " + far_z + "]\n";
}

io::InputError error_of(const fs::path& layout, const mold::MoldSpec& spec) {
  return mtcs_test::thrown_by<io::InputError>([&] { mold::read_layout(layout.string(), spec); }, layout.string());
}

// The plate's spec with +z and -z allowed too: a step along z can be drilled.
mold::MoldSpec spec_drilling_z() {
  std::ifstream in(kMold);
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  const std::string from = "allowed_faces: [+x, -x, +y, -y]";
  text.replace(text.find(from), from.size(), "allowed_faces: [+x, -x, +y, -y, +z, -z]");
  return mold::load_mold_spec(write("plate_z.yaml", text).string());
}

}  // namespace

TEST_CASE("layout as written: a circuit stepping from z = 35 to z = 85 no longer scores like the flat one (refused)",
          "[mold][layout]") {
  const mold::MoldSpec spec = mold::load_mold_spec(kMold);
  const auto flat = mold::read_layout(write("flat.layout.yaml", u_loop("35")).string(), spec);
  CHECK(flat.changes.empty());
  const io::InputError e = error_of(write("step.layout.yaml", u_loop("85")), spec);
  CHECK(e.line() == 6);  // the waypoint [70, 150, 85]
  CHECK(e.column() == 9);
  CHECK(e.field() == "circuits[0].waypoints[2]");
  const std::string what = e.what();
  CHECK_THAT(what, Catch::Contains("circuit 0, waypoint 2 leaves the drilling plane of its inlet (z = 35 mm, here z = 85 mm)"));
  CHECK_THAT(what, Catch::Contains("holes must run parallel to an allowed face"));
  CHECK_THAT(what, Catch::Contains("drilling.allowed_faces (+x, -x, +y, -y)"));
}

TEST_CASE("layout as written: where z can be drilled, the step from z = 35 to z = 85 is scored as written",
          "[mold][layout]") {
  const mold::Scene scene(spec_drilling_z());
  const eval::Pipeline pipeline(scene);
  const auto flat = mold::read_layout(write("flat_z.layout.yaml", u_loop("35")).string(), scene.spec());
  const auto step = mold::read_layout(write("step_z.layout.yaml", u_loop("85")).string(), scene.spec());
  CHECK(step.changes.empty());
  // The written far leg lies at z = 85, 50 mm above the flat one's, and a hole runs along z.
  const mold::Layout drilled = mold::decode(scene, step.genome);
  REQUIRE(drilled.bores.size() == 4);
  CHECK(drilled.bores[1].flow_start.z() == 35);
  CHECK(drilled.bores[1].flow_end.z() == 85);
  CHECK(drilled.bores[3].flow_start.z() == 85);
  CHECK(drilled.bores[3].flow_end.z() == 85);
  // The far leg 20 mm under the cavity (at 105) covers it better than 70 mm under: the worst
  // covered distance (objective 1) drops.
  const auto a = pipeline.evaluate(flat.genome), b = pipeline.evaluate(step.genome);
  CHECK(b.objectives[1] < a.objectives[1]);
}

TEST_CASE("layout as written: a coordinate within 0.01 mm of the inlet's plane is snapped and the change reported",
          "[mold][layout]") {
  const mold::MoldSpec spec = mold::load_mold_spec(kMold);
  const auto w = mold::read_layout(write("near.layout.yaml", u_loop("35.004")).string(), spec);
  REQUIRE(w.changes.size() == 3);
  CHECK(w.changes[0].circuit == 0);
  CHECK(w.changes[0].waypoint == 2);
  CHECK_THAT(w.changes[0].what, Catch::Contains("circuit 0, waypoint 2: z snapped from 35.004 to the inlet's 35 mm"));
  CHECK(w.genome.circuits[0].waypoints[2].z() == 35);
  CHECK(w.genome.circuits[0].waypoints[4].z() == 35);
  // 0.011 mm is beyond the snap: refused.
  CHECK_THAT(std::string(error_of(write("off.layout.yaml", u_loop("35.011")), spec).what()),
             Catch::Contains("leaves the drilling plane"));
}

TEST_CASE("layout as written: a diagonal step is reported as drilled along the axes", "[mold][layout]") {
  const mold::MoldSpec spec = mold::load_mold_spec(kMold);
  const auto w = mold::read_layout(write("diag.layout.yaml",
                                         "circuits:\n  - diameter: 8\n    waypoints: [[70, 0, 35], [100, 150, 35], [130, 0, 35]]\n")
                                       .string(),
                                   spec);
  REQUIRE(w.changes.size() == 2);
  CHECK(w.changes[0].waypoint == 1);
  CHECK_THAT(w.changes[0].what, Catch::Contains("runs along x and y; drilled as 2 axis-parallel holes"));
}

TEST_CASE("layout as written: an empty layout is refused, not silently feasible", "[mold][layout]") {
  const mold::MoldSpec spec = mold::load_mold_spec(kMold);
  const io::InputError e = error_of(write("empty.layout.yaml", "circuits: []\n"), spec);
  CHECK(e.field() == "circuits");
  CHECK_THAT(std::string(e.what()), Catch::Contains("no circuit"));
  const io::InputError p = error_of(write("point.layout.yaml", "circuits:\n  - {diameter: 8, waypoints: [[70, 0, 35], [70, 0, 35]]}\n"), spec);
  CHECK_THAT(std::string(p.what()), Catch::Contains("circuit 0 drills nothing"));
}

TEST_CASE("layout as written: an optimiser's genome off the drilling plane is saved as drilled and re-reads unchanged",
          "[mold][layout]") {
  const mold::Scene scene(mold::load_mold_spec(kMold));
  // An optimiser's genome: waypoints anywhere in z; the decoder keeps the inlet's z.
  mold::Genome g;
  g.circuits.push_back({{{70, 0, 35}, {70, 150, 60.123456}, {100, 160, 85}, {100, 0, 20}}, 8});
  const mold::Genome shop = run::shop_layout(scene, g);
  const fs::path p = write("saved.layout.yaml", "");
  mold::save_layout(p.string(), shop);
  const auto back = mold::read_layout(p.string(), scene.spec());
  CHECK(back.changes.empty());
  const mold::Layout a = mold::decode(scene, g), b = mold::decode(scene, back.genome);
  REQUIRE(a.bores.size() == b.bores.size());
  for (std::size_t i = 0; i < a.bores.size(); ++i) {
    CHECK((a.bores[i].hole.p0 - b.bores[i].hole.p0).norm() < 0.01);
    CHECK((a.bores[i].hole.p1 - b.bores[i].hole.p1).norm() < 0.01);
  }
}
