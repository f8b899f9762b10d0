// Issue 45: a designer's second hour on a part mtcs had not seen. Each defect the trial found,
// run as the trial ran it (the bundled cup stands in for the housing lid): mistakes refused at
// their line before any thermal model is built, the spec's tabs named, a budget of months said
// so, and temperatures no mold can reach flagged.

#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "run_mtcs.h"
#include "support/paths.h"

using namespace mtcs_test;

namespace {

const std::string kCup = MTCS_SOURCE_DIR + "/molds/cup.yaml";

// The bundled cup's layout with its third circuit's far corners moved to x = 300 mm (the block
// ends at 220): the trial's "waypoints outside the block".
fs::path layout_outside() {
  std::string text = read_text(MTCS_SOURCE_DIR + "/molds/cup.layout.yaml");
  text = std::regex_replace(text, std::regex(R"(\[190, 150, 60\])"), "[300, 150, 60]");
  text = std::regex_replace(text, std::regex(R"(\[190, 0, 60\])"), "[300, 0, 60]");
  const fs::path p = scratch("designer_trial", "outside.layout.yaml");
  std::ofstream(p) << text;
  return p;
}

// Whether the command got as far as building the part's thermal model (it says so first).
bool built_model(const std::string& err) { return err.find("thermal model") != std::string::npos; }

}  // namespace

TEST_CASE("designer trial: a waypoint outside the block is refused at its line by evaluate, thermal, interfere and export",
          "[cli][issue45]") {
  // Was: evaluate exit 1 after the model build with "a channel lies outside the block" (no file,
  // line or waypoint); interfere 0 problems; export a bore at x = 300; thermal --tier fd scored it.
  const fs::path layout = layout_outside();
  for (const std::string command : {"evaluate --no-cache", "thermal --no-cache", "thermal --tier fd --no-cache", "interfere",
                                     "export --format csv"}) {
    INFO(command);
    const Run r = run_mtcs_err("designer_trial", command + " " + kCup + " --layout " + layout.string());
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains(layout.string() + ":20:9: field 'circuits[2].waypoints[2]'"));
    CHECK_THAT(r.err, Catch::Contains("circuit 2, waypoint 2 [300, 150, 60] is outside the block: x = 300 mm beyond its +x "
                                      "face at 220 mm"));
    CHECK_FALSE(built_model(r.err));
  }
  CHECK_FALSE(fs::exists(scratch("designer_trial", "outside.layout.csv")));
}

TEST_CASE("designer trial: a missing layout, a missing --start and a used --out fail before the thermal model is built",
          "[cli][issue45]") {
  // Was: each failed only after the model build (39-59 s on the trial's part).
  const fs::path missing = scratch("designer_trial", "no_such.layout.yaml");
  Run r = run_mtcs_err("designer_trial", "evaluate " + kCup + " --layout " + missing.string() + " --no-cache");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains(missing.string() + ": cannot open file"));
  CHECK_FALSE(built_model(r.err));

  const fs::path out = scratch("designer_trial", "run");
  fs::remove_all(out);
  r = run_mtcs_err("designer_trial", "optimize " + kCup + " --start " + missing.string() + " --out " + out.string() + " --no-cache");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains(missing.string() + ": cannot open file"));
  CHECK_FALSE(built_model(r.err));
  CHECK_FALSE(fs::exists(out / "run.sqlite"));

  // A start layout outside the block is refused at its line, before the model, too.
  r = run_mtcs_err("designer_trial", "optimize " + kCup + " --start " + layout_outside().string() + " --out " + out.string() +
                                         " --no-cache");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("circuits[2].waypoints[2]"));
  CHECK_FALSE(built_model(r.err));

  // A folder holding a run: refused (resume it or choose --out) before the model.
  REQUIRE(run_mtcs("optimize " + MTCS_SOURCE_DIR + "/molds/plate.yaml --evaluations 20 --quiet --out " + out.string()) == 0);
  r = run_mtcs_err("designer_trial", "optimize " + kCup + " --evaluations 20 --out " + out.string() + " --no-cache");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("a run exists here: resume it with --resume " + out.string()));
  CHECK_FALSE(built_model(r.err));
}

TEST_CASE("designer trial: a tab in the spec's indentation is named with its line and column", "[cli][issue45]") {
  // Was: "YAML syntax: illegal map value" without a word about tabs.
  std::string spec = read_text(kCup);
  spec = std::regex_replace(spec, std::regex("meshes/"), MTCS_SOURCE_DIR + "/molds/meshes/");
  const std::size_t at = spec.find("  steel_conductivity");
  REQUIRE(at != std::string::npos);
  spec.replace(at, 2, "\t");
  const fs::path p = scratch("designer_trial", "tabbed.yaml");
  std::ofstream(p) << spec;
  const int line = 1 + int(std::count(spec.begin(), spec.begin() + std::ptrdiff_t(at), '\n'));
  const Run r = run_mtcs_err("designer_trial", "evaluate " + p.string() + " --layout " + MTCS_SOURCE_DIR + "/molds/cup.layout.yaml");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("YAML syntax:"));
  CHECK_THAT(r.err, Catch::Contains("(line " + std::to_string(line) + ", column 1 holds a tab: YAML indents with spaces only)"));
}

TEST_CASE("designer trial: a fixed flux that heats the steel above the melt is flagged as physically impossible",
          "[cli][issue45]") {
  // The cup under the old model (a fixed 35 kW/m^2): 262 degC at the core with the melt at 230.
  std::string spec = read_text(kCup);
  spec = std::regex_replace(spec, std::regex("meshes/"), MTCS_SOURCE_DIR + "/molds/meshes/");
  spec = std::regex_replace(spec, std::regex("cavity_condition: coupled"), "heat_flux: 35000");
  const fs::path p = scratch("designer_trial", "cup_flux.yaml");
  std::ofstream(p) << spec;
  const fs::path out = scratch("designer_trial", "thermal.json");
  const int code = run_mtcs("thermal " + p.string() + " --layout " + MTCS_SOURCE_DIR + "/molds/cup.layout.yaml --json > " +
                            out.string(), scratch("designer_trial", "thermal.err"));
  REQUIRE(code == 0);
  const nlohmann::json j = nlohmann::json::parse(read_text(out));
  CHECK(j["max"].get<double>() > 230);
  CHECK(j["above_melt"] == true);
  CHECK_THAT(read_text(scratch("designer_trial", "thermal.err")),
             Catch::Contains("WARNING: physically impossible: the wall reaches"));
  // The bundled (coupled) cup stays below its part's temperature and says nothing.
  REQUIRE(run_mtcs("thermal " + kCup + " --layout " + MTCS_SOURCE_DIR + "/molds/cup.layout.yaml --json > " + out.string()) == 0);
  CHECK(nlohmann::json::parse(read_text(out))["above_melt"] == false);
}

TEST_CASE("designer trial: a budget of days is said once the rate settles, and the time left reads in days", "[cli][issue45]") {
  // Was: no warning and an "ETA 488608287 s". The plate runs at ~10^4 evaluations/s (slower
  // under the sanitizers): 2e9 of them take days. SIGINT once the warning is out (or after 120 s)
  // stops the run (exit 130) with its best so far.
  const fs::path out = scratch("designer_trial", "huge"), err = scratch("designer_trial", "huge.err");
  fs::remove_all(out);
  const fs::path file = scratch("designer_trial", "huge.sh");
  std::ofstream(file) << std::string(MTCS_BINARY) << " optimize " << MTCS_SOURCE_DIR
                      << "/molds/plate.yaml --evaluations 2000000000 --out " << out.string() << " 2>" << err.string()
                      << " & P=$!\nfor i in $(seq 1200); do grep -q 'more: Ctrl-C' " << err.string()
                      << " && break; sleep 0.1; done\nkill -INT $P; wait $P; echo $? > " << err.string() << ".rc\n";
  REQUIRE(std::system(("bash " + file.string()).c_str()) == 0);
  CHECK(read_text(err.string() + ".rc") == "130\n");
  const std::string text = read_text(err);
  // Under the sanitizers the rate is ~100x lower: "more than a year".
  CHECK(std::regex_search(text, std::regex(R"(the budget of 2000000000 evaluations needs ([0-9.]+ (days|h)|more than a year) more)")));
  CHECK(std::regex_search(text, std::regex(R"(ETA ([0-9.]+ (days|h)|more than a year))")));
  CHECK_FALSE(std::regex_search(text, std::regex(R"(ETA [0-9]{6,} s)")));
}

TEST_CASE("designer trial: Ctrl-C while the thermal model builds ends the run within a second, with nothing written",
          "[cli][issue45]") {
  // Was: ignored for 47 s (the model build), then an infeasible generation 0 was written. The
  // gear's cold build takes seconds; SIGINT goes as soon as it says it has begun.
  const fs::path out = scratch("designer_trial", "ctrl_c"), err = scratch("designer_trial", "ctrl_c.err");
  fs::remove_all(out);
  const std::string script = std::string(MTCS_BINARY) + " optimize " + MTCS_SOURCE_DIR + "/molds/gear.yaml --no-cache --out " +
                             out.string() + " 2>" + err.string() + " & P=$!; until grep -q 'thermal model (' " + err.string() +
                             "; do sleep 0.02; done; kill -INT $P; t0=$(date +%s%N); wait $P; rc=$?; "
                             "echo $rc $(( ($(date +%s%N) - t0) / 1000000 )) > " + err.string() + ".rc";
  const fs::path file = scratch("designer_trial", "ctrl_c.sh");
  std::ofstream(file) << script << "\n";
  REQUIRE(std::system(("bash " + file.string()).c_str()) == 0);
  int code = 0, milliseconds = 0;
  std::istringstream(read_text(err.string() + ".rc")) >> code >> milliseconds;
  CHECK(code == 130);
  CHECK(milliseconds < 1000);
  CHECK_THAT(read_text(err), Catch::Contains("interrupted before the search began: nothing was written"));
  CHECK_FALSE(fs::exists(out));
}

TEST_CASE("designer trial: a bore through the part reads 'crosses the part', not 'found 0 mm'", "[cli][issue45]") {
  const fs::path layout = scratch("designer_trial", "through.layout.yaml");
  std::ofstream(layout) << "circuits:\n  - diameter: 8\n    waypoints: [[100, 0, 60], [100, 170, 60], [120, 170, 60], [120, 0, 60]]\n";
  const fs::path out = scratch("designer_trial", "through.txt");
  REQUIRE(run_mtcs("evaluate " + kCup + " --layout " + layout.string() + " > " + out.string()) == 0);
  CHECK_THAT(read_text(out), Catch::Contains("c0.b0 cavity the bore crosses the part (found 0 mm, needs 8 mm)"));
}

TEST_CASE("designer trial: a bore breaking through the block's face scores finite temperatures, infeasible by bore_surface",
          "[cli][issue45]") {
  // Found on the way (a STEP lid with a loop 2 mm under the top face): a 4 mm radius bore 2 mm
  // under a face put its image's axis on its own wall, and every objective came out NaN.
  const fs::path layout = scratch("designer_trial", "breaking.layout.yaml");
  std::ofstream(layout) << "circuits:\n  - diameter: 8\n    waypoints: [[70, 0, 118], [70, 115, 118], [100, 115, 118], [100, 0, 118]]\n";
  const fs::path out = scratch("designer_trial", "breaking.json");
  REQUIRE(run_mtcs("evaluate " + kCup + " --layout " + layout.string() + " --json > " + out.string()) == 0);
  const nlohmann::json j = nlohmann::json::parse(read_text(out));
  for (const auto& [name, value] : j["objectives"].items()) {
    INFO(name);
    CHECK(std::isfinite(value.get<double>()));
  }
  CHECK(j["feasible"] == false);
  bool surface = false;
  for (const auto& v : j["violations"]) surface = surface || v["kind"] == "bore_surface";
  CHECK(surface);
}

TEST_CASE("designer trial: summary.json names the mold by the same absolute path before and after a resume",
          "[cli][issue45]") {
  // Was: the path as given (relative to where optimize ran) in a new run, absolute after a resume.
  const fs::path out = scratch("designer_trial", "relative_run");
  fs::remove_all(out);
  REQUIRE(std::system(("cd " + MTCS_SOURCE_DIR + " && " + MTCS_BINARY + " optimize molds/plate.yaml --evaluations 100 --quiet --out " +
                       out.string()).c_str()) == 0);
  const std::string written = nlohmann::json::parse(read_text(out / "summary.json"))["mold"];
  CHECK(written == (fs::path(MTCS_SOURCE_DIR) / "molds/plate.yaml").lexically_normal().string());
  REQUIRE(run_mtcs("optimize --resume " + out.string() + " --quiet") == 0);
  CHECK(nlohmann::json::parse(read_text(out / "summary.json"))["mold"] == written);
}
