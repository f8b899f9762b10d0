// Bad numbers where a layout enters (issue 15, item 5): NaN, infinities, numbers beyond double
// and 1e308 in a waypoint or a diameter are refused at their line, column and field; denormals
// and -0 are read exactly.

#include <catch2/catch.hpp>

#include "../support/scratch_file.h"
#include "mtcs/io/input_error.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/mold/mold_spec.h"
#include "support/thrown_by.h"
#include "support/paths.h"

using namespace mtcs;

namespace {

const mold::MoldSpec& plate() {
  static const mold::MoldSpec spec = mold::load_mold_spec(MTCS_SOURCE_DIR + "/molds/plate.yaml");
  return spec;
}

// A one-circuit layout of diameter D with its second waypoint [70, Y, 88].
std::string layout(const std::string& d, const std::string& y) {
  return "circuits:\n  - diameter: " + d + "\n    waypoints:\n      - [70, 0, 88]\n      - [70, " + y +
         ", 88]\n      - [100, 0, 88]\n";
}

mold::Genome load(const std::string& text) {
  return mold::load_layout(mtcs_test::write_scratch("layout_bad_numbers", "l.yaml", text).string(), plate());
}

io::InputError error_of(const std::string& text) {
  return mtcs_test::thrown_by<io::InputError>([&] { load(text); }, text);
}

}  // namespace

TEST_CASE("layout bad numbers: NaN, infinities, 1e308 and beyond double are refused at their place", "[mold][bad-numbers]") {
  for (const std::string v : {".nan", "nan", ".inf", "-.inf", "inf", "1e400", "1e308", "-1.7e308", "2e9"}) {
    INFO(v);
    auto e = error_of(layout("8", v));
    CHECK(e.field() == "circuits[0].waypoints[1][1]");
    CHECK(e.line() == 5);
    CHECK(e.column() == 14);
    e = error_of(layout(v, "150"));
    CHECK(e.field() == "circuits[0].diameter");
    CHECK(e.line() == 2);
    CHECK(e.column() == 15);
  }
}

TEST_CASE("layout bad numbers: denormals and -0 are read exactly", "[mold][bad-numbers]") {
  const auto g = load(layout("8", "4.9e-324"));
  CHECK(g.circuits.at(0).waypoints.at(1).y() == 4.9e-324);
  const auto z = load(layout("8", "-0"));
  CHECK(z.circuits.at(0).waypoints.at(1).y() == 0.0);
  // -0 and a denormal are no diameter of the spec's list: named, not divided by.
  CHECK(error_of(layout("-0", "150")).field() == "circuits[0].diameter");
  CHECK(error_of(layout("4.9e-324", "150")).field() == "circuits[0].diameter");
}
