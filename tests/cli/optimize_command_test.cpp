// mtcs optimize end to end: the outputs, determinism across thread counts (identical stored
// generations), and resume after kill -9 ending exactly where an uninterrupted run ends.

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <thread>

#include <unistd.h>

#include "run_mtcs.h"
#include "stored_run.h"
#include "support/paths.h"

namespace fs = std::filesystem;
using mtcs::store::RunStore;

namespace {

fs::path scratch(const std::string& name) { return mtcs_test::scratch("optimize_cli", name); }
using mtcs_test::run_mtcs;

std::vector<std::vector<double>> generations(const fs::path& dir) { return mtcs_test::stored_rows(dir); }

// The plate scored by wall distances: these runs optimise, and the temperatures would make them ~50x slower.
const std::string kMold = MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml";

}  // namespace

TEST_CASE("mtcs optimize writes its results and finds a feasible layout from random starts", "[cli][optimize]") {
  const fs::path dir = scratch("plain");
  fs::remove_all(dir);
  REQUIRE(run_mtcs("optimize " + kMold + " --out " + dir.string() + " --seed 3 --evaluations 6000 --quiet") == 0);
  for (const char* f : {"run.sqlite", "best.layout.yaml", "bores.csv", "bores.stl", "summary.json"})
    CHECK(fs::exists(dir / f));
  // Nothing else: no lock file, journal or temporary left behind by the run's end, nor by a
  // reader of the finished run (read-only: a log it opened it could not remove).
  REQUIRE(run_mtcs("export " + dir.string() + " --format csv --out " + scratch("plain_export.csv").string()) == 0);
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string name = e.path().filename().string();
    INFO(name);
    CHECK((name == "run.sqlite" || name == "best.layout.yaml" || name == "bores.csv" || name == "bores.stl" ||
           name == "holes.csv" || name == "summary.json"));
  }
  std::ifstream in(dir / "summary.json");
  const auto j = nlohmann::json::parse(in);
  CHECK(j["seed"] == 3);
  CHECK(j["evaluations"].get<long>() <= 6000);
  CHECK(j["feasible"].get<bool>());
  // The initial population is random and infeasible; the ES found a feasible layout.
  const RunStore db = RunStore::open((dir / "run.sqlite").string());
  CHECK(db.summaries().front().feasible_share < 1.0);
  // The best layout re-scores to the stored objective.
  CHECK(run_mtcs("evaluate " + kMold + " --layout " + (dir / "best.layout.yaml").string() + " --json > " +
             scratch("rescore.json").string()) == 0);
  std::ifstream rs(scratch("rescore.json"));
  const auto r = nlohmann::json::parse(rs);
  CHECK(r["feasible"].get<bool>());
  CHECK(r["objectives"]["cost"].get<double>() == Approx(j["objectives"]["cost"].get<double>()).epsilon(1e-9));
}

TEST_CASE("mtcs optimize: same seed, same stored generations with 1 or 2 threads", "[cli][optimize][determinism]") {
  const fs::path a = scratch("t1"), b = scratch("t2");
  fs::remove_all(a), fs::remove_all(b);
  REQUIRE(run_mtcs("optimize " + kMold + " --out " + a.string() + " --seed 7 --evaluations 3000 --threads 1 --quiet") == 0);
  REQUIRE(run_mtcs("optimize " + kMold + " --out " + b.string() + " --seed 7 --evaluations 3000 --threads 2 --quiet") == 0);
  const auto ga = generations(a), gb = generations(b);
  CHECK(ga.size() > 100);
  CHECK(ga == gb);
}

TEST_CASE("mtcs optimize: killed with -9 and resumed, it ends exactly as an uninterrupted run", "[cli][optimize]") {
  const fs::path full = scratch("full"), cut = scratch("cut");
  fs::remove_all(full), fs::remove_all(cut);
  const std::string args = " --seed 11 --evaluations 150000 --quiet";
  REQUIRE(run_mtcs("optimize " + kMold + " --out " + full.string() + args) == 0);
  // Start the same run in the background and kill it mid-way.
  const fs::path pid = scratch("pid");
  std::system(("sh -c '" + std::string(MTCS_BINARY) + " optimize " + kMold + " --out " + cut.string() + args +
               " 2>/dev/null & echo $! > " + pid.string() + "'").c_str());
  std::string id;
  for (int i = 0; i < 200 && id.empty(); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    std::ifstream(pid) >> id;
  }
  REQUIRE_FALSE(id.empty());
  // Wait for a few stored generations, then kill.
  for (int i = 0; i < 500; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
    if (fs::exists(cut / "run.sqlite")) {
      try {
        if (RunStore::open((cut / "run.sqlite").string()).summaries().size() >= 20) break;
      } catch (const std::exception&) {
      }
    }
  }
  std::system(("kill -9 " + id + " 2>/dev/null").c_str());
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  const auto stored = RunStore::open((cut / "run.sqlite").string()).summaries().size();
  CHECK(stored < RunStore::open((full / "run.sqlite").string()).summaries().size());  // it was cut short
  REQUIRE(run_mtcs("optimize --resume " + cut.string() + " --quiet") == 0);
  CHECK(generations(cut) == generations(full));
  std::ifstream fa(full / "best.layout.yaml"), fb(cut / "best.layout.yaml");
  std::stringstream sa, sb;
  sa << fa.rdbuf(), sb << fb.rdbuf();
  CHECK(sa.str() == sb.str());
}

TEST_CASE("mtcs optimize --polish refines with COBYLA and stays feasible", "[cli][optimize]") {
  const fs::path dir = scratch("polish");
  fs::remove_all(dir);
  REQUIRE(run_mtcs("optimize " + kMold + " --out " + dir.string() + " --seed 2 --evaluations 4000 --polish 800 --quiet") == 0);
  std::ifstream in(dir / "summary.json");
  const auto j = nlohmann::json::parse(in);
  CHECK(j["feasible"].get<bool>());
  CHECK(j["polish"]["after"].get<double>() <= j["polish"]["before"].get<double>());
  // The written layout is the polished one rounded to 0.01 mm, scored as written.
  CHECK(j["best_objective"].get<double>() == Approx(j["polish"]["after"].get<double>()).epsilon(1e-3));
  CHECK(j["polish"]["evaluations"].get<int>() <= 801);
}

TEST_CASE("issue 16: --polish improves or says why it could not (it used to improve none of 3 runs, silently)",
          "[cli][optimize][issue16]") {
  // The same run twice: polished with a budget too small to move, and with a real one.
  for (const int budget : {1, 300}) {
    INFO(budget);
    const fs::path dir = scratch("polish_why" + std::to_string(budget));
    fs::remove_all(dir);
    const fs::path err = scratch("polish_why.err");
    REQUIRE(run_mtcs("optimize " + kMold + " --out " + dir.string() + " --seed 3 --evaluations 2000 --polish " +
                         std::to_string(budget), err) == 0);
    std::ifstream in(dir / "summary.json");
    const auto p = nlohmann::json::parse(in)["polish"];
    if (p["improved"].get<bool>()) {
      CHECK(p["after"].get<double>() < p["before"].get<double>());
      CHECK_FALSE(p.contains("why_not"));
    } else {
      // The reason, in summary.json and in the warning on stderr.
      const std::string why = p["why_not"].get<std::string>();
      CHECK_FALSE(why.empty());
      CHECK_THAT(mtcs_test::read_text(err), Catch::Contains("found nothing better") && Catch::Contains(why));
      CHECK(p["after"].get<double>() == p["before"].get<double>());
    }
    if (budget == 1) CHECK(p["why_not"].get<std::string>() == "a budget of 1 evaluation is too small (at least 2)");
  }
}

TEST_CASE("mtcs optimize --algorithm sms-emoa on a mold writes its front and hypervolume", "[cli][optimize]") {
  const fs::path dir = scratch("sms");
  fs::remove_all(dir);
  REQUIRE(run_mtcs("optimize " + kMold + " --algorithm sms-emoa --evaluations 1500 --out " + dir.string() + " --quiet") == 0);
  std::ifstream in(dir / "summary.json");
  const auto j = nlohmann::json::parse(in);
  CHECK(j["algorithm"] == "sms-emoa");
  CHECK(j["reference_point"].size() == 3);
  CHECK(j["reference_point"][0].get<double>() > 0);  // in scaled objectives, as every output gives it
  CHECK(j["reference_point_origin"].get<std::string>().find("initial population") != std::string::npos);
  CHECK(j["objective_scales"]["uniformity"].get<double>() == 5);
  CHECK(j["hypervolume"].get<double>() > 0);
  CHECK(fs::exists(dir / "front.csv"));
  const RunStore db = RunStore::open((dir / "run.sqlite").string());
  CHECK(db.summaries().size() >= 10);
}

TEST_CASE("mtcs replay --verify reproduces a stored run, and catches a changed mold", "[cli][replay]") {
  const fs::path dir = scratch("replay"), mold = scratch("replay_plate.yaml");
  fs::remove_all(dir);
  std::ifstream src(kMold);
  std::stringstream text;
  text << src.rdbuf();
  std::ofstream(mold) << text.str();
  REQUIRE(run_mtcs("optimize " + mold.string() + " --out " + dir.string() + " --evaluations 1000 --quiet") == 0);
  CHECK(run_mtcs("replay " + dir.string() + " --verify") == 0);
  CHECK(fs::exists(dir / "replay" / "front_0.csv"));
  CHECK(fs::exists(dir / "replay" / "front_0.json"));
  // A different cost per hole: every stored cost disagrees with the replay.
  std::string changed = text.str();
  const auto at = changed.find("setup: 20");
  REQUIRE(at != std::string::npos);
  changed.replace(at, 9, "setup: 21");
  std::ofstream(mold) << changed;
  CHECK(run_mtcs("replay " + dir.string() + " --verify") == 1);
}

TEST_CASE("mtcs optimize refuses to overwrite a run and reports bad configs", "[cli][optimize]") {
  const fs::path dir = scratch("again");
  fs::remove_all(dir);
  REQUIRE(run_mtcs("optimize " + kMold + " --out " + dir.string() + " --evaluations 200 --quiet") == 0);
  CHECK(run_mtcs("optimize " + kMold + " --out " + dir.string() + " --evaluations 200 --quiet") == 2);
  const fs::path cfg = scratch("bad.yaml");
  std::ofstream(cfg) << "es: {mu: 0}\n";
  CHECK(run_mtcs("optimize " + kMold + " --config " + cfg.string() + " --out " + scratch("bad").string() + " --quiet") == 2);
}

// Issue 16, "Messages": an unwritable --out exited 1 with a filesystem exception; it is bad
// input (exit 2) naming the path, before any work.
TEST_CASE("mtcs optimize: an --out that cannot be created is bad input: exit 2 naming the path", "[cli][optimize][issue16]") {
  for (const std::string out : {"/proc/forbidden/x", "/etc/passwd/x"}) {
    const auto r = mtcs_test::run_mtcs_err("optimize_cli", "optimize " + kMold + " --out " + out + " --evaluations 20 --quiet");
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("mtcs optimize: --out " + out + ": cannot create the folder"));
  }
  const auto r = mtcs_test::run_mtcs_err("optimize_cli", "optimize --problem zdt1 --algorithm sms-emoa --evaluations 200 --out /proc/forbidden/x");
  CHECK(r.code == 2);
  CHECK_THAT(r.err, Catch::Contains("--out /proc/forbidden/x"));
}

// Issue 16: "--evaluations 0" printed a 300-digit range and "--seed -1" ran as seed 2^64 - 1.
TEST_CASE("mtcs optimize: --evaluations 0 and --seed -1 are refused with a readable range", "[cli][optimize][issue16]") {
  const fs::path out = scratch("ranges");
  fs::remove_all(out);
  const auto zero = mtcs_test::run_mtcs_err("optimize_cli", "optimize " + kMold + " --evaluations 0 --out " + out.string());
  CHECK(zero.code == 2);
  CHECK_THAT(zero.err, Catch::Contains("--evaluations: must be a whole number from 1 to 2000000000, got 0"));
  CHECK(zero.err.size() < 200);
  for (const std::string seed : {"-1", "1.5", "x"}) {
    const auto r = mtcs_test::run_mtcs_err("optimize_cli", "optimize " + kMold + " --seed " + seed + " --evaluations 20 --out " + out.string());
    CHECK(r.code == 2);
    CHECK_THAT(r.err, Catch::Contains("--seed: must be a whole number from 0 to 9007199254740992, got " + seed));
  }
  CHECK_FALSE(fs::exists(out / "run.sqlite"));
}

// Issue 16: option errors were printed as "mtcs: :0:0: field 'algorithm': ...".
TEST_CASE("mtcs optimize: option errors name the command and option without a :0:0: place", "[cli][optimize][issue16]") {
  const auto algorithm = mtcs_test::run_mtcs_err("optimize_cli", "optimize --problem zdt1 --algorithm es");
  CHECK(algorithm.code == 2);
  CHECK_THAT(algorithm.err, Catch::StartsWith("mtcs optimize: --algorithm: test problems run with --algorithm sms-emoa"));
  const auto ref = mtcs_test::run_mtcs_err("optimize_cli", "optimize " + kMold + " --ref 1,2 --out " + scratch("ref").string());
  CHECK(ref.code == 2);
  CHECK_THAT(ref.err, Catch::StartsWith("mtcs optimize: --ref: needs one value per objective (3)"));
  const auto resume = mtcs_test::run_mtcs_err("optimize_cli", "optimize --resume " + scratch("nothing").string());
  CHECK(resume.code == 2);
  CHECK_THAT(resume.err, Catch::StartsWith("mtcs optimize: " + (scratch("nothing") / "run.sqlite").string() + ": no run to resume here"));
  for (const auto& r : {algorithm, ref, resume}) CHECK_THAT(r.err, !Catch::Contains(":0:0:"));
}

TEST_CASE("mtcs optimize --start: the run says what the layout scores and ends no worse, bad starts exit 2",
          "[cli][optimize][start]") {
  const std::string layout = MTCS_SOURCE_DIR + "/molds/plate.layout.yaml";
  const fs::path out = scratch("start");
  fs::remove_all(out);
  // What the layout scores, by the other door: mtcs evaluate.
  const fs::path scored = scratch("start_scored.json");
  REQUIRE(mtcs_test::run_mtcs("evaluate " + kMold + " --layout " + layout + " --json >" + scored.string()) == 0);
  const double start = nlohmann::json::parse(mtcs_test::read_text(scored))["scalarised"].get<double>();
  std::ostringstream said;
  said << "start layout " << layout << ": objective " << start;  // 6 digits, as the run prints it
  const auto run = mtcs_test::run_mtcs_err("optimize_cli", "optimize " + kMold + " --start " + layout + " --seed 2 --evaluations 600 --out " + out.string());
  REQUIRE(run.code == 0);
  CHECK_THAT(run.err, Catch::Contains(said.str()));
  std::ifstream in(out / "summary.json");
  CHECK(nlohmann::json::parse(in)["best_objective"].get<double>() <= start);

  // One circuit where the spec's search makes 3-4 (the part's default circuits.min): kept, and said.
  const fs::path one = scratch("start_one");
  fs::remove_all(one);
  const auto few = mtcs_test::run_mtcs_err("optimize_cli", "optimize " + MTCS_SOURCE_DIR + "/docs/first-mold/part.yaml --start "
                                           + MTCS_SOURCE_DIR + "/docs/first-mold/first.layout.yaml --seed 1 --evaluations 300 --out " + one.string());
  CHECK(few.code == 0);
  CHECK_THAT(few.err, Catch::Contains("has 1 drilled circuit; the search makes 3-4 (circuits.min, circuits.max)"));

  const auto problem = mtcs_test::run_mtcs_err("optimize_cli", "optimize --problem zdt1 --algorithm sms-emoa --start " + layout);
  CHECK(problem.code == 2);
  CHECK_THAT(problem.err, Catch::StartsWith("mtcs optimize: --start: a mold's layout; test problems start from samples"));
  const fs::path none = scratch("start_missing");
  fs::remove_all(none);
  const auto missing = mtcs_test::run_mtcs_err("optimize_cli", "optimize " + kMold + " --start nowhere.layout.yaml --out " + none.string());
  CHECK(missing.code == 2);
  CHECK_THAT(missing.err, Catch::Contains("nowhere.layout.yaml"));
  CHECK_FALSE(fs::exists(none));
}

TEST_CASE("mtcs optimize with fidelity: the T3 re-score of the best layout is mtcs thermal --tier fd on it",
          "[cli][optimize][fidelity]") {
  const std::string block = MTCS_SOURCE_DIR + "/molds/thermal_block.yaml";
  const fs::path dir = scratch("fidelity");
  fs::remove_all(dir);
  const fs::path config = scratch("fidelity.yaml");
  std::ofstream(config) << "fidelity: {screen: t1, survivors: 10, final_cell: 4}\n";
  REQUIRE(run_mtcs("optimize " + block + " --config " + config.string() + " --out " + dir.string() +
                   " --seed 2 --evaluations 250 --quiet") == 0);
  std::ifstream in(dir / "summary.json");
  const auto j = nlohmann::json::parse(in);
  REQUIRE(j.contains("t3"));
  CHECK(j["t3"]["cell_mm"].get<double>() == 4);
  CHECK(j["t3"]["seconds"].get<double>() > 0);
  const fs::path t3 = scratch("fidelity_t3.json");
  REQUIRE(run_mtcs("thermal " + block + " --layout " + (dir / "best.layout.yaml").string() +
                   " --tier fd --cell 4 --json > " + t3.string()) == 0);
  std::ifstream ts(t3);
  const auto r = nlohmann::json::parse(ts);
  for (const char* k : {"mean", "std", "max"})
    CHECK(j["t3"][k].get<double>() == Approx(r[k].get<double>()).epsilon(1e-12));
  // The stored objectives are the spec's tier (T2d), not the screen's: the re-score by
  // mtcs evaluate (T2d) gives them back.
  const fs::path ev = scratch("fidelity_eval.json");
  REQUIRE(run_mtcs("evaluate " + block + " --layout " + (dir / "best.layout.yaml").string() + " --json > " +
                   ev.string()) == 0);
  std::ifstream es(ev);
  const auto e = nlohmann::json::parse(es);
  CHECK(e["objectives"]["temperature_std"].get<double>() ==
        Approx(j["objectives"]["temperature_std"].get<double>()).epsilon(1e-9));
}
