// mtcs interfere MOLD --layout: a layout built to cross an ejector pin and to pass 1 mm under the
// plate cavity is reported with the closed-form distances and the places they occur.

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include "run_mtcs.h"
#include "support/paths.h"

using namespace mtcs_test;

TEST_CASE("mtcs interfere MOLD --layout: crossings and shortfalls with their places", "[cli][interfere]") {
  // The plate: ejector0 is the pin x = 60, y = 35, z 0..105, radius 3; the cavity's underside is
  // z = 105 over x 50..250, y 25..175. Circuit 0 runs along y at x = 60, z = 60, through the pin;
  // circuit 1 at z = 100 with 8 mm bores: 105 - 104 = 1 mm of steel, the clearance is 1.0D = 8.
  const fs::path layout = scratch("interfere", "bad.layout.yaml");
  std::ofstream(layout) << "circuits:\n"
                           "  - {diameter: 8, waypoints: [[60, 0, 60], [60, 150, 60], [90, 150, 60], [90, 0, 60]]}\n"
                           "  - {diameter: 8, waypoints: [[150, 0, 100], [150, 150, 100], [180, 150, 100], [180, 0, 100]]}\n";
  const fs::path out = scratch("interfere", "report.json");
  REQUIRE(run_mtcs(std::string("interfere ") + MTCS_SOURCE_DIR + "/molds/plate.yaml --layout " + layout.string() +
                   " --json > " + out.string()) == 0);
  const auto report = nlohmann::json::parse(read_text(out));
  bool pin = false;
  int under = 0;
  for (const auto& v : report.at("violations")) {
    const auto where = v.at("where");
    if (v.at("against") == "ejector0") {
      pin = true;
      CHECK(v.at("interferes") == true);
      CHECK(v.at("distance").get<double>() == 0);
      CHECK(where[0].get<double>() == Approx(60).margin(3));
      CHECK(where[1].get<double>() == Approx(35).margin(3 + 4));
      CHECK(where[2].get<double>() == Approx(60).margin(4));
    }
    if (v.at("against") == "cavity") {
      ++under;
      CHECK(v.at("interferes") == false);
      CHECK(v.at("distance").get<double>() == Approx(1).epsilon(1e-12));
      CHECK(v.at("clearance").get<double>() == Approx(8));
      CHECK(where[2].get<double>() == Approx(104.5).margin(1e-9));
    }
  }
  CHECK(pin);
  CHECK(under == 3);  // the three holes of circuit 1 under the plate
  CHECK(report.at("pairs").get<int>() >= 1);
  CHECK(report.at("distance").get<double>() == 0);

  // The bundled reference layout is clean; a missing layout is a user error (exit 2).
  CHECK(run_mtcs(std::string("interfere ") + MTCS_SOURCE_DIR + "/molds/plate.yaml --layout " + MTCS_SOURCE_DIR +
                 "/molds/plate.layout.yaml > /dev/null") == 0);
  CHECK(run_mtcs(std::string("interfere ") + MTCS_SOURCE_DIR + "/molds/plate.yaml --layout nowhere.yaml > /dev/null") == 2);
}
