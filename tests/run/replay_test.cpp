// Issue 16, item 4: replay writes its folder whole or not at all (a temporary folder renamed at
// the end; what a killed replay left is cleared), and by default files for a sample of the
// stored generations, with --every N and --all for more.

#include <catch2/catch.hpp>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>

#include <unistd.h>

#include "mtcs/io/input_error.h"
#include "mtcs/opt/hypervolume.h"
#include "mtcs/run/anytime_trace.h"
#include "mtcs/run/replay.h"
#include "mtcs/run/stored_run.h"
#include "support/scratch_file.h"
#include "support/paths.h"

using namespace mtcs;
namespace fs = std::filesystem;

namespace {

run::ReplayChoice every(int n) {
  run::ReplayChoice c;
  c.every = n;
  return c;
}
run::ReplayChoice all() {
  run::ReplayChoice c;
  c.all = true;
  return c;
}
run::ReplayChoice only(int generation) {
  run::ReplayChoice c;
  c.generation = generation;
  return c;
}

std::vector<int> steps(int first, int last, int step) {
  std::vector<int> v;
  for (int i = first; i <= last; i += step) v.push_back(i);
  return v;
}

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> hidden_entries(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().filename().string().front() == '.') out.push_back(e.path().filename().string());
  return out;
}

}  // namespace

TEST_CASE("issue 16: replay files a sample of generations by default, --every N and --all on request", "[run][replay][issue16]") {
  const std::vector<int> stored = steps(0, 600, 10);  // 61 stored generations
  // About kReplaySample: every second one here (61 / 50 rounded up), from the first, and the last.
  CHECK(run::replayed_generations(stored, {}, "run.sqlite") == steps(0, 600, 20));
  std::vector<int> every7 = steps(0, 560, 70);
  every7.push_back(600);  // the last one always
  CHECK(run::replayed_generations(stored, every(7), "run.sqlite") == every7);
  CHECK(run::replayed_generations(stored, all(), "run.sqlite") == stored);
  CHECK(run::replayed_generations(stored, only(40), "run.sqlite") == std::vector<int>{40});
  CHECK_THROWS_AS(run::replayed_generations(stored, only(41), "run.sqlite"), io::InputError);
  // 6 000 stored steps (a 1.3 s SMS-EMOA run stored every 10): 50 frames, not 600.
  CHECK(run::replayed_generations(steps(0, 5990, 10), {}, "run.sqlite").size() <= std::size_t(run::kReplaySample) + 1);
}

TEST_CASE("issue 16: replay writes DIR/replay whole or not at all", "[run][replay][issue16]") {
  const fs::path dir = mtcs_test::fresh_scratch_dir("replay", "run");
  fs::create_directories(dir);
  run::RunOverrides o;
  o.algorithm = "sms-emoa";
  o.seed = 3;
  o.evaluations = 300;
  o.config = MTCS_TEST_DATA + "/configs/no_reach.yaml";  // a fixed number of steps per budget
  const run::Session session(MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml", o);
  const run::MoldOptimizer optimizer(session.problem(), session.scene(), session.config());
  store::RunStore db = store::RunStore::create((dir / "run.sqlite").string(), {{"mold", "plate"}});
  run::run_stored(optimizer, session.problem(), db, {});
  REQUIRE(db.summaries().size() == 30);  // steps 0, 10, ..., 290 (the initial population counts 10)

  const auto first = run::write_replay(session, db, dir.string(), {});
  CHECK(first.mismatches == 0);
  CHECK(first.checked == 30 * 10);  // every stored generation re-evaluated
  CHECK(first.generations == 30);
  const std::string frames = read_text(dir / "replay" / "frames.json");
  CHECK(nlohmann::json::parse(frames)["frames"].size() == 30);
  CHECK(hidden_entries(dir).empty());

  // A replay that fails before its end (here the plots step throws) leaves the previous folder
  // as it was and no temporary behind.
  CHECK_THROWS(run::write_replay(session, db, dir.string(), every(10),
                                 [](const fs::path&) { throw std::runtime_error("plotting failed"); }));
  CHECK(read_text(dir / "replay" / "frames.json") == frames);
  CHECK(hidden_entries(dir).empty());

  // What a replay killed with -9 left (a staged folder of a process that is gone) is cleared,
  // and the new replay replaces the old folder whole: no front of the old sample remains.
  fs::create_directories(dir / ".replay.tmp-999999999");
  std::ofstream(dir / ".replay.tmp-999999999" / "front_10.csv") << "partial";
  const auto second = run::write_replay(session, db, dir.string(), every(10));
  CHECK(second.generations == 4);  // 0, 100, 200 and the last, 290
  CHECK(nlohmann::json::parse(read_text(dir / "replay" / "frames.json"))["frames"].size() == 4);
  CHECK_FALSE(fs::exists(dir / "replay" / "front_20.csv"));
  CHECK(fs::exists(dir / "replay" / "front_100.csv"));
  CHECK(hidden_entries(dir).empty());
  fs::remove_all(dir);
}

TEST_CASE("issue 14: replay writes the run's anytime trace (best and hypervolume against evaluations and time)", "[run][replay][anytime]") {
  const fs::path dir = mtcs_test::fresh_scratch_dir("replay", "anytime");
  fs::create_directories(dir);
  run::RunOverrides o;
  o.algorithm = "sms-emoa";
  o.seed = 5;
  o.evaluations = 400;
  const run::Session session(MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml", o);
  const run::MoldOptimizer optimizer(session.problem(), session.scene(), session.config());
  store::RunStore db = store::RunStore::create((dir / "run.sqlite").string(), {{"mold", "plate"}});
  run::run_stored(optimizer, session.problem(), db, {});
  run::write_replay(session, db, dir.string(), every(10));  // the trace covers every stored generation anyway

  std::ifstream in(dir / "replay" / "anytime.csv");
  std::string line;
  std::getline(in, line);
  CHECK(line == "generation,evaluations,seconds,best_feasible,best_so_far,hypervolume,hypervolume_so_far");
  const auto summaries = db.summaries();
  double best = std::numeric_limits<double>::infinity(), most = 0;
  std::size_t k = 0;
  for (; std::getline(in, line); ++k) {
    REQUIRE(k < summaries.size());
    std::vector<double> v;
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');) v.push_back(std::stod(cell));
    REQUIRE(v.size() == 7);
    CHECK(int(v[0]) == summaries[k].index);
    CHECK(long(v[1]) == summaries[k].evaluations);
    CHECK(v[2] == Approx(summaries[k].seconds).epsilon(1e-8));
    // By hand from the stored population: the best feasible value, the front's hypervolume in
    // scaled objectives against the run's reference point.
    const opt::Generation g = *db.generation(summaries[k].index);
    double here = std::numeric_limits<double>::infinity();
    std::vector<opt::Point> front;
    for (std::size_t i = 0; i < g.population.size(); ++i) {
      const auto& a = g.population[i].score;
      if (!a.feasible) continue;
      here = std::min(here, a.value);
      bool dominated = false;
      for (const auto& other : g.population) {
        const auto& b = other.score;
        bool no_worse = b.feasible, better = false;
        for (std::size_t j = 0; j < a.objectives.size() && no_worse; ++j)
          no_worse = b.objectives[j] <= a.objectives[j], better = better || b.objectives[j] < a.objectives[j];
        dominated = dominated || (no_worse && better);
      }
      if (dominated) continue;
      opt::Point p = a.objectives;
      for (std::size_t j = 0; j < p.size(); ++j) p[j] /= optimizer.scales()[j];
      front.push_back(p);
    }
    const double hv = opt::hypervolume(front, optimizer.scaled_reference());
    best = std::min(best, here);
    most = std::max(most, hv);
    if (std::isinf(here)) CHECK(std::isinf(v[3]));
    else CHECK(v[3] == Approx(here).epsilon(1e-9));
    if (!std::isinf(best)) CHECK(v[4] == Approx(best).epsilon(1e-9));
    CHECK(v[5] == Approx(hv).epsilon(1e-8).margin(1e-12));
    CHECK(v[6] == Approx(most).epsilon(1e-8).margin(1e-12));
  }
  CHECK(k == summaries.size());
  CHECK(most > 0);
  CHECK(nlohmann::json::parse(read_text(dir / "replay" / "frames.json"))["anytime"] == "anytime.csv");
  fs::remove_all(dir);
}

TEST_CASE("replay: an ES run's hypervolumes are against its first generation's reference point, not 0", "[run][replay][anytime]") {
  // A new user's find: every ES run's anytime hypervolume was 0 (a fixed 4 per scaled
  // objective: the plate's temperature_max / 10 is ~8).
  const fs::path dir = mtcs_test::fresh_scratch_dir("replay", "anytime_es");
  fs::create_directories(dir);
  run::RunOverrides o;
  o.seed = 2;
  o.evaluations = 250;
  const run::Session session(MTCS_SOURCE_DIR + "/molds/plate.yaml", o);
  const run::MoldOptimizer optimizer(session.problem(), session.scene(), session.config());
  REQUIRE_FALSE(optimizer.pareto());
  CHECK(optimizer.reference_from_first_generation());
  store::RunStore db = store::RunStore::create((dir / "run.sqlite").string(), {{"mold", "plate"}});
  const opt::Generation last = run::run_stored(optimizer, session.problem(), db, {}).last;
  const run::AnytimeTrace trace = run::stored_anytime(optimizer, db);
  // SMS-EMOA's rule on a fresh sample of the same seed and size: the same point.
  CHECK(trace.reference() == run::scaled_reference(session.config(), session.problem(), session.spec().objectives));
  const std::vector<opt::Point> front = opt::SmsEmoa::front(last);
  REQUIRE_FALSE(front.empty());
  CHECK(optimizer.scaled_hypervolume(front, std::vector<double>(front[0].size(), 4.0)) == 0);  // the old point
  CHECK(trace.rows().back().hypervolume == Approx(optimizer.scaled_hypervolume(front, trace.reference())));
  CHECK(trace.rows().back().hypervolume_so_far > 0);
}
