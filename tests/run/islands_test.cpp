// Issue 15, item 1: islands in one process. The same seed and P give the same store whatever
// the thread count; one island is the plain run; an interrupted archipelago resumed ends as the
// uninterrupted one; migration moves what it should (ES: the best replace the worst; SMS-EMOA:
// the front members of largest hypervolume contribution, computed here by hand).

#include <catch2/catch.hpp>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>
#include <unistd.h>

#include "mtcs/opt/migration.h"
#include "mtcs/opt/sms_emoa.h"
#include "mtcs/run/optimize_run.h"
#include "../support/scratch_file.h"
#include "run/island_wire.h"
#include "support/paths.h"

using namespace mtcs;
namespace fs = std::filesystem;

namespace {

const std::string kMold = MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml";

fs::path scratch(const std::string& name) { return mtcs_test::fresh_scratch_dir("islands", name); }

run::OptimizeRequest request(const fs::path& out, int islands, const std::string& algorithm = "es") {
  run::OptimizeRequest r;
  r.mold = kMold;
  r.out = out.string();
  r.overrides.algorithm = algorithm;
  r.overrides.seed = 7;
  r.overrides.evaluations = algorithm == "es" ? 1200 : 900;
  r.prepare_out = [](const std::string& dir) { fs::create_directories(dir); };
  r.islands.islands = islands;
  r.islands.migration_every = 2;
  r.islands.migrants = 2;
  return r;
}

run::OptimizeResult optimize(const run::OptimizeRequest& r, const std::function<bool()>& stop = {}) {
  return run::optimize_mold(r, [](const run::MoldOptimizer&, int) { return run::ProgressSink(); }, stop);
}

// Bit patterns, so that -0 and NaN compare as stored.
std::vector<std::uint64_t> bits(const std::vector<double>& v) {
  std::vector<std::uint64_t> out(v.size());
  if (!v.empty()) std::memcpy(out.data(), v.data(), v.size() * sizeof(double));
  return out;
}

// Every stored row but the wall times: the run's generations, then each island's.
std::vector<std::vector<std::uint64_t>> rows(const fs::path& dir, int islands) {
  const auto db = store::RunStore::open((dir / "run.sqlite").string());
  std::vector<std::vector<std::uint64_t>> out;
  auto add = [&](const opt::Generation& g, int island) {
    for (const auto& ind : g.population) {
      std::vector<std::uint64_t> row{std::uint64_t(island), std::uint64_t(g.index), std::uint64_t(g.evaluations)};
      for (const auto* v : {&ind.x, &ind.steps, &ind.score.objectives}) {
        const auto b = bits(*v);
        row.insert(row.end(), b.begin(), b.end());
      }
      const auto s = bits({ind.score.violation, ind.score.value});
      row.insert(row.end(), s.begin(), s.end());
      out.push_back(row);
    }
  };
  for (const auto& s : db.summaries()) add(*db.generation(s.index), -1);
  for (int i = 0; i < islands; ++i)
    for (const auto& s : db.island_summaries(i)) add(*db.island_generation(i, s.index), i);
  return out;
}

// A problem of one coordinate: value = x, better = smaller.
struct Line final : opt::Problem {
  std::string name() const override { return "line"; }
  opt::Genotype sample(opt::Rng& rng) const override { return {rng.uniform()}; }
  std::vector<double> initial_steps(const opt::Genotype&) const override { return {0.1}; }
  long mutate(opt::Genotype&, const std::vector<double>&, opt::Rng&) const override { return 0; }
  opt::Score evaluate(const opt::Genotype& g) const override { return {{g[0], 1 - g[0]}, 0, true, g[0], ""}; }
};

opt::Individual member(double f1, double f2) { return {{f1}, {0.1}, {{f1, f2}, 0, true, f1, ""}}; }

}  // namespace

TEST_CASE("islands: the same seed and P give the same store with 1 thread or all", "[run][islands]") {
  for (const std::string algorithm : {"es", "sms-emoa"}) {
    const fs::path a = scratch("threads_all_" + algorithm), one = scratch("threads_one_" + algorithm);
    optimize(request(a, 3, algorithm));
    {
      tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
      optimize(request(one, 3, algorithm));
    }
    const auto ra = rows(a, 3);
    CHECK(ra.size() > 100);
    CHECK(ra == rows(one, 3));
    // One row per island and stored generation, and the archipelago's own.
    const auto db = store::RunStore::open((a / "run.sqlite").string());
    for (int i = 0; i < 3; ++i) CHECK(db.island_summaries(i).size() == db.summaries().size());
    CHECK(db.island_summaries(3).empty());
    // The archipelago's count is its islands' (which differ: the reach move's evaluations count).
    long sum = 0;
    for (int i = 0; i < 3; ++i) sum += db.island_summaries(i).back().evaluations;
    CHECK(db.summaries().back().evaluations == sum);
    CHECK(sum >= 1200);
  }
}

TEST_CASE("islands: one island is the plain run of the same seed", "[run][islands]") {
  for (const std::string algorithm : {"es", "sms-emoa"}) {
    const fs::path island = scratch("one_island_" + algorithm), plain = scratch("plain_" + algorithm);
    optimize(request(island, 1, algorithm));
    optimize(request(plain, 0, algorithm));
    auto main_rows = [](const fs::path& dir) {
      auto r = rows(dir, 0);
      return r;
    };
    CHECK(main_rows(island) == main_rows(plain));
  }
}

TEST_CASE("islands: an interrupted archipelago resumed ends as the uninterrupted one", "[run][islands]") {
  // Migration delays 0 (lockstep), 1 and 2: a resume sends again the migrants then on their way.
  for (const int delay : {0, 1, 2})
    for (const std::string algorithm : {"es", "sms-emoa"}) {
      INFO(algorithm << ", migration delay " << delay);
      const std::string name = algorithm + "_" + std::to_string(delay);
      const fs::path whole = scratch("whole_" + name), parts = scratch("parts_" + name);
      auto r = request(whole, 4, algorithm);
      r.islands.topology = opt::Topology::fully_connected;
      r.islands.migration_delay = delay;
      const run::OptimizeResult done = optimize(r);
      CHECK_FALSE(done.interrupted);
      // stop() is read where the islands meet and ends the run `delay` meetings later: stopped at
      // the islands' 4th meeting, then resumed.
      r.out = parts.string();
      int calls = 0;
      const run::OptimizeResult stopped = optimize(r, [&] { return ++calls > 3 - delay; });
      CHECK(stopped.interrupted);
      CHECK(stopped.last_generation < done.last_generation);
      run::OptimizeRequest again;
      again.resume = parts.string();
      const run::OptimizeResult resumed = optimize(again);
      CHECK_FALSE(resumed.interrupted);
      CHECK(resumed.last_generation == done.last_generation);
      CHECK(rows(parts, 4) == rows(whole, 4));
    }
}

TEST_CASE("islands: a migration delay changes the run, resuming twice still ends as the uninterrupted run",
          "[run][islands]") {
  // The delay is part of the run (its arrivals come at other generations), and a resume in the
  // middle of the migrants' way, stopped again, still ends where the whole run ends.
  const fs::path lockstep = scratch("delay_0"), delayed = scratch("delay_3"), parts = scratch("delay_3_parts");
  auto r = request(lockstep, 3);
  r.islands.migration_every = 1;
  r.islands.migration_delay = 0;
  optimize(r);
  r.out = delayed.string(), r.islands.migration_delay = 3;
  optimize(r);
  CHECK(rows(lockstep, 3) != rows(delayed, 3));
  r.out = parts.string();
  int calls = 0;
  CHECK(optimize(r, [&] { return ++calls > 1; }).interrupted);
  run::OptimizeRequest again;
  again.resume = parts.string();
  calls = 0;
  CHECK(optimize(again, [&] { return ++calls > 0; }).interrupted);
  CHECK_FALSE(optimize(again).interrupted);
  CHECK(rows(parts, 3) == rows(delayed, 3));
}

TEST_CASE("islands: kill -9 while the store thread writes, every resume ends as the uninterrupted run",
          "[run][islands][kill]") {
  // The mtcs binary with MTCS_CRASH_AT=store-island-row:N (SIGKILL at the N-th island row, in the
  // writer thread), then --resume: the rows, bit for bit, of the run never killed.
  const std::string args = " optimize " + kMold + " --islands 4 --migration-every 2 --migrants 2 --seed 7"
                           " --evaluations 1200 --threads 2 --quiet --out ";
  const fs::path whole = scratch("kill_whole");
  REQUIRE(std::system((std::string(MTCS_BINARY) + args + whole.string() + " 2>/dev/null").c_str()) == 0);
  const auto expected = rows(whole, 4);
  for (const int n : {1, 17, 95, 203, 311}) {  // of 320 island rows
    INFO("killed at island row " << n);
    const fs::path dir = scratch("kill_" + std::to_string(n));
    const int killed = std::system(
        ("MTCS_CRASH_AT=store-island-row:" + std::to_string(n) + " " + MTCS_BINARY + args + dir.string() + " 2>/dev/null")
            .c_str());
    CHECK(WEXITSTATUS(killed) == 128 + SIGKILL);  // sh reports its child's SIGKILL as 137
    if (!fs::exists(dir / "run.sqlite")) continue;
    CHECK(rows(dir, 4).size() < expected.size());
    REQUIRE(std::system((std::string(MTCS_BINARY) + " optimize --resume " + dir.string() + " --quiet 2>/dev/null").c_str()) ==
            0);
    CHECK(rows(dir, 4) == expected);
  }
}

TEST_CASE("islands: restarts fire on the islands, resumed across them, or on one thread, the run is the same",
          "[run][islands][restart]") {
  // Stalls made frequent (2 generations without a 20 % gain): the stall counts travel in the store,
  // and a resume between restarts must restart where the uninterrupted run did.
  const fs::path config = scratch("restart_config") / "run.yaml";
  fs::create_directories(config.parent_path());
  std::ofstream(config) << "es:\n  restart_after: 2\n  restart_tolerance: 0.2\n";
  const fs::path whole = scratch("restart_whole"), parts = scratch("restart_parts"), one = scratch("restart_one");
  auto r = request(whole, 3);
  r.overrides.config = config.string();
  r.overrides.evaluations = 2400;
  const run::OptimizeResult done = optimize(r);
  auto stall_counts = [](const fs::path& dir) {
    const auto db = store::RunStore::open((dir / "run.sqlite").string());
    std::vector<int> out;
    for (int i = 0; i < 3; ++i)
      for (const auto& s : db.island_summaries(i)) out.push_back(db.island_generation(i, s.index)->stalled);
    return out;
  };
  const std::vector<int> stalls = stall_counts(whole);
  // A restart follows every positive multiple of 2 that is not an island's last generation.
  const auto restarts = std::count_if(stalls.begin(), stalls.end(), [](int k) { return k > 0 && k % 2 == 0; });
  CHECK(restarts >= 3);
  {
    tbb::global_control single(tbb::global_control::max_allowed_parallelism, 1);
    r.out = one.string();
    optimize(r);
  }
  CHECK(rows(one, 3) == rows(whole, 3));
  CHECK(stall_counts(one) == stalls);
  r.out = parts.string();
  int calls = 0;
  CHECK(optimize(r, [&] { return ++calls > 3; }).interrupted);
  run::OptimizeRequest again;
  again.resume = parts.string();
  const run::OptimizeResult resumed = optimize(again);
  CHECK(resumed.last_generation == done.last_generation);
  CHECK(rows(parts, 3) == rows(whole, 3));
  CHECK(stall_counts(parts) == stalls);
}

TEST_CASE("islands: settings survive the store's text, bad ones name the field", "[run][islands]") {
  run::IslandSettings s;
  s.islands = 5, s.migration_every = 3, s.migrants = 4, s.topology = opt::Topology::fully_connected;
  s.migration_delay = 2;
  const auto back = run::IslandSettings::parse(s.to_text(), "meta");
  CHECK(back.migration_delay == 2);
  // A store made before the delay existed migrated in lockstep.
  CHECK(run::IslandSettings::parse("islands: 2\nmigration_every: 3\n", "meta").migration_delay == 0);
  CHECK_THROWS_WITH(run::IslandSettings::parse("islands: 2\nmigration_delay: -1\n", "meta"), Catch::Contains("delay"));
  CHECK(back.islands == 5);
  CHECK(back.migration_every == 3);
  CHECK(back.migrants == 4);
  CHECK(back.topology == opt::Topology::fully_connected);
  CHECK_THROWS_WITH(run::IslandSettings::parse("islands: 2\ntopology: star\n", "meta"), Catch::Contains("topology"));
  CHECK_THROWS_WITH(run::IslandSettings::parse("islands: 0\n", "meta"), Catch::Contains("islands"));
}

TEST_CASE("islands: who receives from whom, island 0 keeps the run's seed", "[opt][islands]") {
  CHECK(opt::migration_sources(opt::Topology::ring, 4, 0) == std::vector<int>{3});
  CHECK(opt::migration_sources(opt::Topology::ring, 4, 2) == std::vector<int>{1});
  CHECK(opt::migration_sources(opt::Topology::fully_connected, 4, 2) == std::vector<int>{0, 1, 3});
  CHECK(opt::migration_sources(opt::Topology::ring, 1, 0).empty());
  CHECK(opt::island_seed(42, 0) == 42);
  std::vector<std::uint64_t> seeds;
  for (int i = 0; i < 64; ++i) seeds.push_back(opt::island_seed(42, i));
  std::sort(seeds.begin(), seeds.end());
  CHECK(std::adjacent_find(seeds.begin(), seeds.end()) == seeds.end());
}

TEST_CASE("islands: ES migrants are the best, and replace the worst only when better", "[opt][islands]") {
  const Line line;
  opt::Generation g;
  for (const double v : {0.1, 0.3, 0.5, 0.7}) g.population.push_back(member(v, 1 - v));
  const auto out = opt::best_emigrants(g, 2);
  REQUIRE(out.size() == 2);
  CHECK(out[0].score.value == 0.1);
  CHECK(out[1].score.value == 0.3);
  // Arrivals 0.2 and 0.9: 0.2 displaces the worst (0.7); 0.9 is worse than all and stays out.
  const auto after = opt::replace_worst(line, g, {member(0.9, 0.1), member(0.2, 0.8)});
  std::vector<double> values;
  for (const auto& ind : after.population) values.push_back(ind.score.value);
  CHECK(values == std::vector<double>{0.1, 0.2, 0.3, 0.5});
}

TEST_CASE("islands: SMS-EMOA sends front members by hypervolume contribution and reduces arrivals away", "[opt][islands]") {
  const Line line;
  opt::SmsConfig c;
  c.mu = 4;
  c.ref = {5, 5};
  const opt::SmsEmoa sms(line, c);
  // Front (1,4), (2,2), (4,1) against (5,5): exclusive boxes 1x1, 2x2, 1x1; (3,3) is dominated.
  opt::Generation g;
  for (const auto& p : std::vector<std::pair<double, double>>{{3, 3}, {1, 4}, {2, 2}, {4, 1}})
    g.population.push_back(member(p.first, p.second));
  const auto out = sms.emigrants(g, 2);
  REQUIRE(out.size() == 2);
  CHECK(out[0].score.objectives == std::vector<double>{2, 2});  // contribution 4
  CHECK(out[1].score.objectives == std::vector<double>{1, 4});  // 1, tied with (4,1): the earlier
  CHECK(sms.emigrants(g, 10).size() == 3);                      // the front only
  // An arrival that dominates (3,3) and (2,2)'s box corner: (1.5,1.5) comes in, the dominated
  // (3,3) goes; a dominated arrival (4.5,4.5) goes itself.
  const auto after = sms.immigrate(g, {member(1.5, 1.5), member(4.5, 4.5)});
  REQUIRE(after.population.size() == 4);
  std::vector<std::vector<double>> kept;
  for (const auto& ind : after.population) kept.push_back(ind.score.objectives);
  CHECK(std::count(kept.begin(), kept.end(), std::vector<double>{1.5, 1.5}) == 1);
  CHECK(std::count(kept.begin(), kept.end(), std::vector<double>{3, 3}) == 0);
  CHECK(std::count(kept.begin(), kept.end(), std::vector<double>{4.5, 4.5}) == 0);
}

TEST_CASE("islands: messages between ranks keep every bit", "[run][islands]") {
  opt::Generation g;
  g.index = 12, g.evaluations = 1234567890123L, g.stalled = 77;
  g.population.push_back({{-0.0, 4.9e-324, 1e308}, {std::nan("")}, {{1, 2}, 0.5, false, 3.25, "bore 2 too close"}});
  g.population.push_back({{}, {}, {{}, 0, true, -1, ""}});
  const opt::Generation back = run::wire::decode_generation(run::wire::encode(g));
  CHECK(back.index == 12);
  CHECK(back.evaluations == 1234567890123L);
  CHECK(back.stalled == 77);
  REQUIRE(back.population.size() == 2);
  CHECK(bits(back.population[0].x) == bits(g.population[0].x));
  CHECK(bits(back.population[0].steps) == bits(g.population[0].steps));
  CHECK(back.population[0].score.detail == "bore 2 too close");
  CHECK_FALSE(back.population[0].score.feasible);
  CHECK(back.population[1].score.value == -1);
  CHECK_THROWS(run::wire::decode_generation(run::wire::encode(g).substr(0, 30)));
  // An island's generations between two meetings, in one message.
  opt::Generation next = g;
  next.index = 13, next.population.pop_back();
  const auto both = run::wire::decode_generations(run::wire::encode(std::vector<opt::Generation>{g, next}));
  REQUIRE(both.size() == 2);
  CHECK(both[0].index == 12);
  CHECK(both[0].population.size() == 2);
  CHECK(both[1].index == 13);
  REQUIRE(both[1].population.size() == 1);
  CHECK(bits(both[1].population[0].x) == bits(g.population[0].x));
  CHECK(run::wire::decode_generations(run::wire::encode(std::vector<opt::Generation>{})).empty());
}

TEST_CASE("islands: a rank's default threads share the machine's cores with the other ranks on it", "[run][islands]") {
  const char* saved_size = std::getenv("OMPI_COMM_WORLD_SIZE");
  const char* saved_local = std::getenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  if (saved_size || saved_local || std::getenv("PMI_SIZE")) return;  // under mpirun itself: leave it be
  const int cores = int(std::thread::hardware_concurrency());
  CHECK(run::threads_per_rank() == 0);  // not under mpirun: all cores
  ::setenv("OMPI_COMM_WORLD_SIZE", "4", 1);
  ::setenv("OMPI_COMM_WORLD_LOCAL_SIZE", "2", 1);
  CHECK(run::threads_per_rank() == std::max(1, cores / 2));
  ::setenv("OMPI_COMM_WORLD_LOCAL_SIZE", "4096", 1);
  CHECK(run::threads_per_rank() == 1);
  ::unsetenv("OMPI_COMM_WORLD_SIZE");
  ::unsetenv("OMPI_COMM_WORLD_LOCAL_SIZE");
}
