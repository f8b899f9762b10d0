// mtcs evaluate end to end: the JSON contract and bad input (exit code 2, file:line:column).

#include <catch2/catch.hpp>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include <unistd.h>

#include "support/scratch_file.h"
#include "support/paths.h"
#include "support/bundled_variant.h"

namespace fs = std::filesystem;

namespace {

struct Run {
  int code;
  std::string out, err;
};

fs::path scratch(const std::string& name) { return mtcs_test::scratch_dir("eval_cli") / name; }

Run run_mtcs(const std::string& args) {
  const fs::path out = scratch("run.out"), err = scratch("run.err");
  const int status = std::system((std::string(MTCS_BINARY) + " " + args + " >" + out.string() + " 2>" + err.string()).c_str());
  auto slurp = [](const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
  };
  return {WEXITSTATUS(status), slurp(out), slurp(err)};
}

}  // namespace

TEST_CASE("mtcs evaluate --json prints one object with the documented fields", "[cli]") {
  // The gear under a fixed flux, its void ignored: the fields are the same, its model builds in a
  // fraction (sanitised).
  const std::string gear = mtcs_test::bundled_variant(
      "gear", {{"cavity_condition: coupled", "heat_flux: 17000"}, {"cavity_void: surface\n  void_panel: 8", "cavity_void: ignore"}});
  const Run r = run_mtcs("evaluate " + gear + " --layout " + MTCS_SOURCE_DIR + "/molds/gear.layout.yaml --json");
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["feasible"].is_boolean());
  CHECK(j["objectives"].contains("temperature_std"));
  CHECK(j["objectives"].contains("cost"));
  CHECK(j["violations"].is_array());
  bool mesh_stage = false;
  for (const auto& s : j["stages"]) {
    CHECK(s["seconds"].get<double>() >= 0);
    mesh_stage = mesh_stage || s["name"] == "bore_cavity_mesh";
  }
  CHECK(mesh_stage);
}

TEST_CASE("mtcs evaluate --json: `scalarised` is the objective mtcs optimize gives its best", "[cli]") {
  // A new user could not check "objective 11.15" of a run against a hand-made layout.
  const fs::path run = scratch("run");
  fs::remove_all(run);
  REQUIRE(run_mtcs("optimize " + MTCS_SOURCE_DIR + "/molds/plate.yaml --evaluations 300 --seed 4 --quiet --out " + run.string()).code == 0);
  const auto summary = nlohmann::json::parse(std::ifstream(run / "summary.json"));
  const Run r = run_mtcs("evaluate " + MTCS_SOURCE_DIR + "/molds/plate.yaml --layout " + (run / "best.layout.yaml").string() + " --json");
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["scalarised"].get<double>() == Approx(summary["best_objective"].get<double>()).epsilon(1e-9));
  // molds/plate.yaml's scales: temperature_std 1 K, cycle_time 1 s, cost 1000.
  const auto& o = j["objectives"];
  const double by_hand = o["temperature_std"].get<double>() + o["cycle_time"].get<double>() + o["cost"].get<double>() / 1000;
  if (j["feasible"].get<bool>()) CHECK(j["scalarised"].get<double>() == Approx(by_hand).epsilon(1e-12));
}

TEST_CASE("mtcs evaluate reports violations with elements, distance and margin", "[cli]") {
  const fs::path layout = scratch("gap.layout.yaml");
  // Two straight bores 10 mm apart (gap 2 mm for 8 mm bores) across the plate's block.
  std::ofstream(layout) << "circuits:\n"
                           "  - {diameter: 8, waypoints: [[100, 0, 80], [100, 200, 80], [100, 200, 80]]}\n"
                           "  - {diameter: 8, waypoints: [[110, 0, 80], [110, 100, 80], [300, 100, 80]]}\n";
  const Run r = run_mtcs("evaluate " + MTCS_SOURCE_DIR + "/molds/plate.yaml --layout " + layout.string() + " --json");
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  CHECK_FALSE(j["feasible"].get<bool>());
  bool found = false;
  for (const auto& v : j["violations"])
    if (v["kind"] == "bore_bore" && v["elements"][0] == "c0.b0" && v["elements"][1] == "c1.b0")
      found = std::abs(v["distance"].get<double>() - 2) < 1e-9 && v["margin"] == 4;
  CHECK(found);
}

TEST_CASE("mtcs evaluate rejects bad input with exit code 2", "[cli]") {
  const fs::path layout = scratch("bad.layout.yaml");
  std::ofstream(layout) << "circuits:\n  - {diameter: 7, waypoints: [[0, 0, 0], [1, 1, 1]]}\n";
  Run r = run_mtcs("evaluate " + MTCS_SOURCE_DIR + "/molds/plate.yaml --layout " + layout.string());
  CHECK(r.code == 2);
  CHECK(r.err.find(layout.string() + ":2:16:") != std::string::npos);
  CHECK(r.err.find("circuits[0].diameter") != std::string::npos);
  CHECK(r.err.find("(6, 8, 10 mm)") != std::string::npos);  // the drills the plate allows
  r = run_mtcs("evaluate /nonexistent.yaml --layout " + layout.string());
  CHECK(r.code == 2);
}

// Issue 16, "Messages": violation lines read "found 30, needs 4" with no unit. Clearances are in
// mm; the depth limit is a depth/diameter ratio (c0.b0 runs 200 mm with an 8 mm drill: 25).
TEST_CASE("mtcs evaluate prints violation lines with units: mm for clearances and the depth ratio", "[cli][issue16]") {
  const fs::path layout = scratch("units.layout.yaml"), mold = scratch("shallow.yaml");
  std::ofstream(layout) << "circuits:\n"
                           "  - {diameter: 8, waypoints: [[100, 0, 80], [100, 200, 80], [100, 200, 80]]}\n"
                           "  - {diameter: 8, waypoints: [[110, 0, 80], [110, 100, 80], [300, 100, 80]]}\n";
  std::ifstream in(MTCS_SOURCE_DIR + "/molds/plate.yaml");
  std::stringstream spec;
  spec << in.rdbuf();
  std::string text = spec.str();
  const std::string limit = "max_depth_ratio: 50";
  REQUIRE(text.find(limit) != std::string::npos);
  text.replace(text.find(limit), limit.size(), "max_depth_ratio: 10");
  std::ofstream(mold) << text;
  const Run r = run_mtcs("evaluate " + mold.string() + " --layout " + layout.string());
  REQUIRE(r.code == 0);
  CHECK_THAT(r.out, Catch::Contains("bore_bore      c0.b0 c1.b0 found 2 mm, needs 4 mm at ("));
  CHECK_THAT(r.out, Catch::Contains("depth_ratio    c0.b0 depth/diameter 25, at most 10 at (100, 200, 80) mm"));
  CHECK_THAT(r.out, Catch::Contains("outlet_face    c0 200 mm from the nearest allowed face"));
  CHECK_THAT(r.out, !Catch::Matches("(.|\n)*found [0-9.e+-]+, (.|\n)*"));
}

TEST_CASE("mtcs evaluate gives each bore's drillable evidence, and its draw command gives the same map",
          "[cli][drillable]") {
  const fs::path spec = scratch("gear_angled.yaml"), layout = scratch("gear_angled.layout.yaml");
  std::ofstream(spec) << "block: {box: {min: [0, 0, 0], max: [160, 160, 90]}}\n"
                         "cavity: {mesh: " + MTCS_TEST_DATA + "/meshes/mcad_herringbone_gear.off, translate: [80, 80, 55]}\n"
                         "drilling: {diameters: [8], axis_parallel: false, max_angle_deg: 30,\n"
                         "           access_map: {grid: 32, cells: [16, 16]}}\n"
                         "circuits: {inlet_faces: [-y], outlet_faces: [-y]}\n"
                         // The wall distances: a void model of the gear takes minutes under ASan.
                         "objectives: {use: [uniformity, worst_covered, cost]}\n";
  // One U: in through the gear at x = 60 (blocked), across behind it, out at x = 140 (free).
  std::ofstream(layout) << "circuits:\n  - diameter: 8\n    waypoints: [[60, 0, 55], [60, 130, 55], [140, 130, 55], [140, 0, 55]]\n";
  const Run r = run_mtcs("evaluate " + spec.string() + " --layout " + layout.string() + " --json");
  REQUIRE(r.code == 0);
  const auto j = nlohmann::json::parse(r.out);
  REQUIRE(j["drillable"].size() == 3);
  CHECK(j["drillable"][0]["free"] == false);
  CHECK(j["drillable"][2]["free"] == true);
  bool violation = false;
  for (const auto& v : j["violations"]) violation = violation || (v["kind"] == "drillable" && v["elements"][0] == "c0.b0");
  CHECK(violation);
  for (const auto& b : j["drillable"]) {
    CHECK(b["map"] == nlohmann::json::array({16, 16}));
    // The pointer, run with the exact CheckBox (an independent method) to a CSV.
    std::string draw = b["draw"];
    const fs::path csv = scratch("am.csv");
    draw.replace(draw.find("--out am.png"), 12, "--method checkbox --out " + csv.string());
    REQUIRE(run_mtcs(draw.substr(std::string("mtcs ").size())).code == 0);
    std::ifstream in(csv);
    std::string line;
    long free = 0;
    std::getline(in, line);
    while (std::getline(in, line)) free += line.back() == '1';
    CHECK(free == b["free_cells"]);
  }
  const Run text = run_mtcs("evaluate " + spec.string() + " --layout " + layout.string());
  CHECK(text.out.find("c0.b0 blocked, cell (") != std::string::npos);
  CHECK(text.out.find("draw: mtcs access-map ") != std::string::npos);
}
