// mtcs thermal and mtcs bench thermal as a user runs them: the reference block's cavity
// temperature against FreeFem++, temperatures at a CSV's points, field files, bad input.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <nlohmann/json.hpp>

#include "run_mtcs.h"
#include "support/bundled_variant.h"
#include "support/paths.h"

using namespace mtcs_test;

namespace {

const std::string kMold = std::string(MTCS_SOURCE_DIR) + "/molds/thermal_block.yaml";
const std::string kLayout = std::string(MTCS_SOURCE_DIR) + "/molds/thermal_block.layout.yaml";
const std::string kSamples = std::string(MTCS_TEST_DATA) + "/thermal/patch_samples.csv";

// x,y,z,T rows of a CSV with a header.
std::vector<std::array<double, 4>> read_xyzt(const fs::path& p) {
  std::ifstream in(p);
  std::string line;
  std::getline(in, line);
  std::vector<std::array<double, 4>> rows;
  std::array<double, 4> r;
  char c;
  while (in >> r[0] >> c >> r[1] >> c >> r[2] >> c >> r[3]) rows.push_back(r);
  return rows;
}

}  // namespace

TEST_CASE("mtcs thermal --json: the reference block as FreeFem++ has it", "[cli][thermal]") {
  const fs::path out = scratch("thermal", "summary.json");
  REQUIRE(run_mtcs("thermal " + kMold + " --layout " + kLayout + " --json >" + out.string()) == 0);
  const auto j = nlohmann::json::parse(read_text(out));
  // shared/cases/thermal/README.md: sample mean 55.6609 degC, std 2.5612 K, max 59.004 degC;
  // the physical-proxy bars.
  CHECK(j["tier"] == "t2d");
  CHECK(j["mean"].get<double>() == Approx(55.6609).margin(0.25));
  CHECK(j["std"].get<double>() == Approx(2.5612).margin(0.15));
  CHECK(j["max"].get<double>() == Approx(59.004).margin(0.35));
  CHECK(j["heat_in"].get<double>() == Approx(144).epsilon(1e-9));
  CHECK(j["seconds"].get<double>() > 0);
}

TEST_CASE("mtcs thermal --json: each side of a parted mold, none on an unparted one", "[cli][thermal]") {
  const fs::path plate = scratch("thermal", "plate_sides.json"), block = scratch("thermal", "block_sides.json");
  REQUIRE(run_mtcs("thermal " + MTCS_SOURCE_DIR + "/molds/plate.yaml --layout " + MTCS_SOURCE_DIR +
                   "/molds/plate.layout.yaml --json >" + plate.string()) == 0);
  const auto j = nlohmann::json::parse(read_text(plate));
  // The plate is parted at its top face, which takes no heat (not among the heated samples): the
  // cavity side is every heated sample, the bottom and the rim, 200 x 150 + 2 (200 + 150) 3 mm^2.
  CHECK(j["sides"]["core"]["area"] == 0);
  CHECK(j["sides"]["core"]["std"].is_null());
  CHECK(j["sides"]["cavity"]["area"].get<double>() == Approx(32100));
  CHECK(j["sides"]["cavity"]["std"].get<double>() == Approx(j["std"].get<double>()));
  REQUIRE(run_mtcs("thermal " + kMold + " --layout " + kLayout + " --json >" + block.string()) == 0);
  CHECK_FALSE(nlohmann::json::parse(read_text(block)).contains("sides"));
}

TEST_CASE("mtcs thermal --json: each circuit's flow, drop and rise with a flow rate, none at a wall temperature",
          "[cli][thermal][hydraulics]") {
  const fs::path plate = scratch("thermal", "plate_coolant.json"), block = scratch("thermal", "block_coolant.json");
  REQUIRE(run_mtcs("thermal " + MTCS_SOURCE_DIR + "/molds/plate.yaml --layout " + MTCS_SOURCE_DIR +
                   "/molds/plate.layout.yaml --json >" + plate.string()) == 0);
  const auto j = nlohmann::json::parse(read_text(plate));
  REQUIRE(j.contains("coolant"));
  const auto& circuits = j["coolant"]["circuits"];
  REQUIRE(circuits.size() == 3);  // the hand-made layout's three U loops
  double heat = 0;
  for (const auto& c : circuits) {
    CHECK(c["flow"] == 8);
    CHECK(c["turns"] == 2);
    CHECK(c["pressure_drop"]["total"].get<double>() > 0);
    CHECK(c["rise"].get<double>() > 0);
    heat += c["heat"].get<double>();
  }
  CHECK(heat == Approx(j["heat_to_bores"].get<double>()).epsilon(1e-9));
  CHECK(j["coolant"]["checks"].empty());
  REQUIRE(run_mtcs("thermal " + kMold + " --layout " + kLayout + " --json >" + block.string()) == 0);
  CHECK_FALSE(nlohmann::json::parse(read_text(block)).contains("coolant"));  // Dirichlet bores: no flow given
}

TEST_CASE("mtcs thermal --samples: temperatures at the user's points", "[cli][thermal]") {
  const fs::path out = scratch("thermal", "T.csv");
  REQUIRE(run_mtcs("thermal " + kMold + " --layout " + kLayout + " --tier fd --cell 2 --samples " + kSamples +
                   " --out " + out.string() + " >/dev/null") == 0);
  const auto ours = read_xyzt(out), reference = read_xyzt(kSamples);
  REQUIRE(ours.size() == 720);
  double sq = 0;
  for (std::size_t i = 0; i < ours.size(); ++i) {
    CHECK(ours[i][0] == reference[i][0]);
    sq += (ours[i][3] - reference[i][3]) * (ours[i][3] - reference[i][3]);
  }
  CHECK(std::sqrt(sq / 720) < 0.25);  // finite volumes at 2 mm: 0.18 K (experiments/thermal/fv.md)
}

TEST_CASE("mtcs thermal --out: a field ParaView opens, and bad input refused", "[cli][thermal]") {
  const fs::path vtp = scratch("thermal", "field.vtp");
  REQUIRE(run_mtcs("thermal " + kMold + " --layout " + kLayout + " --tier t2 --out " + vtp.string() + " >/dev/null") == 0);
  const std::string text = read_text(vtp);
  CHECK(text.find("<VTKFile type=\"PolyData\"") != std::string::npos);
  CHECK(text.find("Scalars=\"temperature [degC]\"") != std::string::npos);  // ParaView's active array, by its name
  CHECK(text.find("Name=\"temperature [degC]\"") != std::string::npos);
  // A field in a format we do not write, --samples without --out: exit 2, nothing written.
  const auto bad = run_mtcs_err("thermal", "thermal " + kMold + " --layout " + kLayout + " --out " +
                                               scratch("thermal", "field.txt").string());
  CHECK(bad.code == 2);
  CHECK(bad.err.find(".vtp, .ply or .png") != std::string::npos);
  CHECK_FALSE(fs::exists(scratch("thermal", "field.txt")));
  CHECK(run_mtcs("thermal " + kMold + " --layout " + kLayout + " --samples " + kSamples) == 2);
  // A malformed points CSV: file, line and field.
  const fs::path points = scratch("thermal", "points.csv");
  std::ofstream(points) << "x,y,z\n1,2,3\n4,five,6\n";
  const auto malformed = run_mtcs_err("thermal", "thermal " + kMold + " --layout " + kLayout + " --samples " +
                                                     points.string() + " --out " + scratch("thermal", "t.csv").string());
  CHECK(malformed.code == 2);
  CHECK(malformed.err.find("points.csv:3:") != std::string::npos);
  CHECK(malformed.err.find("'y'") != std::string::npos);
  CHECK_FALSE(fs::exists(scratch("thermal", "t.csv")));
  // Points with no steel temperature (a new user's find: a point outside the block got a number,
  // one on a bore's axis NaN, both with exit 0): exit 2, the point's line, why, nothing written.
  for (const auto& [row, why] : {std::pair{"400,0,0", "outside the block"}, std::pair{"60,40,47.5", "inside bore c1.b0"}}) {
    std::ofstream(points) << "x,y,z\n# a comment line\n60,10,50\n" << row << "\n";
    const auto outside = run_mtcs_err("thermal", "thermal " + kMold + " --layout " + kLayout + " --samples " +
                                                   points.string() + " --out " + scratch("thermal", "t.csv").string());
    CHECK(outside.code == 2);
    CHECK(outside.err.find("points.csv:4:") != std::string::npos);
    CHECK(outside.err.find(why) != std::string::npos);
    CHECK_FALSE(fs::exists(scratch("thermal", "t.csv")));
  }
}

TEST_CASE("mtcs bench thermal --json: every tier judged against the finite volumes", "[cli][thermal]") {
  const fs::path out = scratch("thermal", "bench.json");
  REQUIRE(run_mtcs("bench thermal --case block --layouts 6 --reference-cell 4 --repeat 1 --json >" + out.string()) == 0);
  const auto j = nlohmann::json::parse(read_text(out));
  CHECK(j["default_tier"] == "t2d M=4");
  REQUIRE(j["tiers"].size() >= 5);
  bool fd_self = false;
  for (const auto& t : j["tiers"]) {
    for (const char* key : {"tier", "ms_full", "ms_incremental", "rms_k", "tau_std"}) CHECK(t.contains(key));
    // The reference tier judged against itself: exact.
    if (t["tier"] == "fd h=4 mm") fd_self = t["rms_k"].get<double>() == 0 && t["tau_std"].get<double>() == 1;
  }
  CHECK(fd_self);
  for (const auto& t : j["tiers"])  // no part, no cycle, no sides
    CHECK((t["tau_cycle"].is_null() && t["tau_difference"].is_null() && t["tau_std_side"].is_null()));
}

TEST_CASE("mtcs bench thermal on a mold: the tau of cycle_time, temperature_difference and temperature_std_side",
          "[cli][thermal]") {
  const fs::path out = scratch("thermal", "bench_plate.json");
  REQUIRE(run_mtcs("bench thermal --case " + std::string(MTCS_SOURCE_DIR) + "/molds/plate.yaml --layouts 5 --reference-cell 4 "
                   "--repeat 1 --tiers \"t0,fd h=4\" --difference --json >" + out.string()) == 0);
  const auto j = nlohmann::json::parse(read_text(out));
  REQUIRE(j["tiers"].size() == 2);
  for (const auto& t : j["tiers"]) {
    REQUIRE(t["tau_cycle"].is_number());
    REQUIRE(t["tau_difference"].is_number());
    REQUIRE(t["tau_std_side"].is_number());  // the plate is parted at its top face
    // The reference judged against itself ranks alike (and the layouts differ: a tau of 0 would
    // say every score tied).
    if (t["tier"] == "fd h=4 mm")
      CHECK((t["tau_cycle"] == 1.0 && t["tau_difference"] == 1.0 && t["tau_std_side"] == 1.0));
  }
}

TEST_CASE("mtcs bench thermal on a mold drillable along one axis: random straight bores", "[cli][thermal]") {
  // molds/thermal_block.yaml drills along x only: a random circuit is one bore through (it
  // crashed drawing a second axis that is not there).
  const fs::path out = scratch("thermal", "bench_thermal_block.json");
  REQUIRE(run_mtcs("bench thermal --case " + std::string(MTCS_SOURCE_DIR) + "/molds/thermal_block.yaml --layouts 3 "
                   "--reference-cell 4 --repeat 1 --tiers \"t2d M=4,fd h=4\" --json >" + out.string()) == 0);
  const auto j = nlohmann::json::parse(read_text(out));
  REQUIRE(j["tiers"].size() == 2);
  for (const auto& t : j["tiers"])
    if (t["tier"] == "t2d M=4") CHECK(t["rms_k"].get<double>() < 1.0);  // against the finite volumes at 4 mm: 0.27 K
}

TEST_CASE("mtcs bench thermal refuses a reference too fine for the block, before solving", "[cli][thermal]") {
  const fs::path err = scratch("thermal", "bench_too_fine.err");
  // 300 x 200 x 120 mm at 0.5 mm: 57.6 M cells.
  CHECK(run_mtcs("bench thermal --case " + std::string(MTCS_SOURCE_DIR) + "/molds/plate.yaml --layouts 3 "
                 "--reference-cell 0.5",
                 err) == 2);
  const std::string text = read_text(err);
  CHECK(text.find("--reference-cell: 0.5 mm makes 57.6 M cells") != std::string::npos);
  CHECK(text.find("use 0.63 mm or coarser") != std::string::npos);  // 476 x 317 x 190 = 28.7 M

}

TEST_CASE("mtcs optimize with temperature objectives: the same run on 1 and 2 threads, replayed bit for bit", "[cli][thermal]") {
  // The line sinks keep a cache per thread; a cached evaluation must equal a cold one.
  std::string summary[2];
  for (int threads = 1; threads <= 2; ++threads) {
    const fs::path out = scratch("thermal", "run" + std::to_string(threads));
    fs::remove_all(out);
    REQUIRE(run_mtcs("optimize " + kMold + " --evaluations 400 --seed 3 --quiet --threads " + std::to_string(threads) +
                     " --out " + out.string() + " >/dev/null") == 0);
    std::istringstream in(read_text(out / "summary.json"));
    for (std::string line; std::getline(in, line);)
      if (line.find("seconds") == std::string::npos) summary[threads - 1] += line + "\n";
  }
  CHECK(summary[0].find("temperature_std") != std::string::npos);
  CHECK(summary[0] == summary[1]);
  CHECK(run_mtcs("replay " + scratch("thermal", "run2").string() + " --verify --no-plots --quiet >/dev/null") == 0);
}

TEST_CASE("mtcs thermal --problem: the conduction problem for another solver, as the model holds it", "[cli][thermal]") {
  const fs::path problem = scratch("thermal", "problem.json"), summary = scratch("thermal", "problem_summary.json");
  REQUIRE(run_mtcs("thermal " + kMold + " --layout " + kLayout + " --problem " + problem.string() + " --json >" +
                   summary.string()) == 0);
  const auto j = nlohmann::json::parse(read_text(problem));
  // The reference block (shared/cases/thermal/README.md): 120 x 80 x 60 mm, k 30 W/(m K), three
  // Dirichlet bores of 10, 8 and 10 mm (molds/thermal_block.layout.yaml), a patch taking 144 W,
  // 720 samples on it.
  CHECK(j["block"]["max"][0] == 120.0);
  CHECK(j["conductivity"].get<double>() == Approx(30));
  REQUIRE(j["channels"].size() == 3);
  const double radii[] = {5, 4, 5};
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(j["channels"][i]["radius"] == radii[i]);
    CHECK(j["channels"][i]["film"].is_null());  // Dirichlet
  }
  double heat = 0;
  for (const auto& t : j["cavity"]) {
    const auto& c = t["corners"];
    const double ux = c[1][0].get<double>() - c[0][0].get<double>(), uy = c[1][1].get<double>() - c[0][1].get<double>(),
                 vx = c[2][0].get<double>() - c[0][0].get<double>(), vy = c[2][1].get<double>() - c[0][1].get<double>();
    heat += 0.5 * std::abs(ux * vy - uy * vx) * 1e-6 * t["flux"].get<double>();
  }
  CHECK(heat == Approx(nlohmann::json::parse(read_text(summary))["heat_in"].get<double>()).epsilon(1e-9));
  CHECK(j["samples"].size() == 720);
  CHECK(nlohmann::json::parse(read_text(summary))["cavity_condition"]["model"] == "flux");
  CHECK_FALSE(j["channels"][0].contains("capacity_W_K"));  // Dirichlet bores: no flow, no warming
  // The plate's flow: each channel's circuit, place and rho Q c_p, for a solver that warms the coolant.
  const fs::path plate = scratch("thermal", "plate_problem.json");
  REQUIRE(run_mtcs("thermal " + MTCS_SOURCE_DIR + "/molds/plate.yaml --layout " + MTCS_SOURCE_DIR +
                   "/molds/plate.layout.yaml --problem " + plate.string() + " >/dev/null") == 0);
  const auto p = nlohmann::json::parse(read_text(plate));
  REQUIRE(p["channels"].size() >= 9);
  for (const auto& c : p["channels"]) {
    CHECK(c["capacity_W_K"].get<double>() == Approx(992.2 * (8e-3 / 60) * 4179).epsilon(0.005));  // water at 40 C, 8 l/min
    CHECK(c["circuit"].get<int>() >= 0);
  }
}

TEST_CASE("mtcs thermal --out on a mesh part: the field in chunks, as at the same points asked for", "[cli][thermal]") {
  // The cup's field has 13 822 vertices, past the 4 096 a model takes at once (its memory): the
  // chunks' temperatures are those of the same points asked for with --samples (one model), to
  // the float coordinates' rounding, and the summary does not change with --out.
  const std::string cup = std::string(MTCS_SOURCE_DIR) + "/molds/cup.yaml --layout " + MTCS_SOURCE_DIR +
                          "/molds/cup.layout.yaml";
  const fs::path vtp = scratch("thermal_chunks", "field.vtp"), plain = scratch("thermal_chunks", "plain.json"),
                 with_field = scratch("thermal_chunks", "field.json");
  REQUIRE(run_mtcs("thermal " + cup + " --json > " + plain.string()) == 0);
  REQUIRE(run_mtcs("thermal " + cup + " --json --out " + vtp.string() + " > " + with_field.string()) == 0);
  auto a = nlohmann::json::parse(read_text(plain)), b = nlohmann::json::parse(read_text(with_field));
  a.erase("seconds"), b.erase("seconds");
  CHECK(a == b);
  // The vertices and their temperatures (ascii, 17 digits: the doubles as computed).
  const std::string text = read_text(vtp);
  const auto array_after = [&](const std::string& tag) {
    const std::size_t at = text.find('>', text.find(tag)) + 1;
    std::istringstream in(text.substr(at, text.find('<', at) - at));
    std::vector<double> v;
    for (double x; in >> x;) v.push_back(x);
    return v;
  };
  const std::vector<double> t = array_after("Name=\"temperature [degC]\""), xyz = array_after("NumberOfComponents=\"3\"");
  REQUIRE(t.size() > 3 * 4096);
  REQUIRE(xyz.size() == 3 * t.size());
  const fs::path points = scratch("thermal_chunks", "points.csv"), at = scratch("thermal_chunks", "T.csv");
  {
    std::ofstream out(points);
    out << std::setprecision(17) << "x,y,z\n";
    for (std::size_t i = 0; i < t.size(); ++i) out << xyz[3 * i] << ',' << xyz[3 * i + 1] << ',' << xyz[3 * i + 2] << '\n';
  }
  REQUIRE(run_mtcs("thermal " + cup + " --samples " + points.string() + " --out " + at.string() + " >/dev/null") == 0);
  const auto asked = read_xyzt(at);
  REQUIRE(asked.size() == t.size());
  double worst = 0;
  for (std::size_t i = 0; i < t.size(); ++i) worst = std::max(worst, std::abs(asked[i][3] - t[i]));
  CHECK(worst < 1e-3);  // K; an order of vertices lost between chunks would miss by kelvins
}

TEST_CASE("mtcs thermal: a part too big for the memory allowed is refused with the size it needs", "[cli][thermal]") {
  // The L-bracket's model: 378 void panels and ~2 300 samples, ~10 MB at the samples; 5 MB allowed.
  const std::string bracket = std::string(MTCS_SOURCE_DIR) + "/molds/l_bracket.yaml --layout " + MTCS_SOURCE_DIR +
                              "/molds/l_bracket.layout.yaml";
  const fs::path err = scratch("thermal_memory", "run.err");
  const auto run_with_limit = [&](const std::string& megabytes) {
    return run_mtcs("thermal " + bracket + " >/dev/null", err, "MTCS_MEMORY_LIMIT=" + megabytes);
  };
  CHECK(run_with_limit("5") == 1);
  const std::string refused = read_text(err);
  INFO(refused);
  CHECK(refused.find("needs about ") != std::string::npos);
  CHECK(refused.find(" MB more for its ") != std::string::npos);
  CHECK(refused.find("378 void panels") != std::string::npos);
  CHECK(refused.find("thermal.sample_spacing") != std::string::npos);
  CHECK(run_with_limit("1000") == 0);
}

TEST_CASE("mtcs optimize: summary.json gives each circuit's coolant and says which circuit breaks a shop limit",
          "[cli][thermal][hydraulics]") {
  // The plate with a coolant rise limit below what any of its layouts reaches at 8 l/min.
  const std::string mold = bundled_variant("plate", "coolant: {temperature: 40, flow_rate: 8}",
                                           "coolant: {temperature: 40, flow_rate: 8, max_rise: 0.05}");
  const fs::path out = scratch("thermal", "run_rise"), log = scratch("thermal", "run_rise.log");
  const fs::path scored = scratch("thermal", "run_rise_best.json");
  fs::remove_all(out);
  REQUIRE(run_mtcs("optimize " + mold + " --evaluations 60 --seed 3 --out " + out.string() + " >/dev/null", log) == 0);
  const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
  REQUIRE(summary.contains("coolant"));
  REQUIRE_FALSE(summary["violations"].empty());
  CHECK(summary["feasible"] == false);
  // Each circuit's rise over the limit is a violation of that circuit, on the screen too.
  for (const auto& c : summary["coolant"]["circuits"]) {
    const std::string name = "c" + std::to_string(c["circuit"].get<int>());
    bool listed = false;
    for (const auto& v : summary["violations"])
      listed = listed || (v["kind"] == "coolant_rise" && v["elements"][0] == name &&
                          v["found"].get<double>() == Approx(c["rise"].get<double>()).epsilon(1e-9));
    CHECK(listed);
    CHECK_THAT(read_text(log), Catch::Contains("best layout: coolant_rise " + name + ": coolant rise"));
  }
  // The same numbers as mtcs evaluate gives the written best.
  REQUIRE(run_mtcs("evaluate " + mold + " --layout " + (out / "best.layout.yaml").string() + " --json >" + scored.string()) == 0);
  const auto best = nlohmann::json::parse(read_text(scored));
  REQUIRE(best["coolant"]["circuits"].size() == summary["coolant"]["circuits"].size());
  for (std::size_t k = 0; k < best["coolant"]["circuits"].size(); ++k)
    CHECK(best["coolant"]["circuits"][k]["heat"].get<double>() ==
          Approx(summary["coolant"]["circuits"][k]["heat"].get<double>()).epsilon(1e-12));
}

TEST_CASE("mtcs optimize: every bundled mold's best keeps the shop's coolant limits, or its summary names the circuit",
          "[cli][thermal][hydraulics]") {
  // Short runs: each circuit of the best as summary.json tabulates it has a coolant_* violation
  // exactly when its numbers break a limit (Reynolds under 10 000, rise over 3 K; a table and a
  // verdict that disagree fail here). On the bundled molds none does (issue 42's target); the
  // limits binding is the plate's case above (max_rise 0.05).
  for (const std::string mold : {"plate", "cup", "gear", "l_bracket", "ribbed_box"}) {
    const fs::path out = scratch("thermal", "shop_" + mold);
    fs::remove_all(out);
    REQUIRE(run_mtcs("optimize " + MTCS_SOURCE_DIR + "/molds/" + mold + ".yaml --evaluations 200 --seed 1 --quiet --out " +
                     out.string() + " >/dev/null") == 0);
    const auto summary = nlohmann::json::parse(read_text(out / "summary.json"));
    INFO(mold << ": " << summary["violations"].dump());
    REQUIRE(summary.contains("coolant"));
    REQUIRE_FALSE(summary["coolant"]["circuits"].empty());
    for (const auto& c : summary["coolant"]["circuits"]) {
      const std::string name = "c" + std::to_string(c["circuit"].get<int>());
      const bool breaks = c["reynolds"].get<double>() < 1e4 || c["rise"].get<double>() > 3;
      bool named = false;
      for (const auto& v : summary["violations"])
        named = named || (v["kind"].get<std::string>().rfind("coolant_", 0) == 0 && v["elements"][0] == name);
      CHECK(named == breaks);
      CHECK_FALSE(breaks);
    }
  }
}
