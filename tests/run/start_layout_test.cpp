// mtcs optimize --start: a designer's layout opens the first population. The ES ends no worse
// than it (plus selection); the run store keeps it exactly, so an interrupted run resumes as the
// uninterrupted one and a replay rebuilds the same reference point; a start that cannot be read
// is refused before anything is written.

#include <catch2/catch.hpp>

#include <algorithm>
#include <filesystem>

#include "mtcs/io/input_error.h"
#include "mtcs/run/optimize_run.h"
#include "mtcs/run/run_record.h"
#include "mtcs/run/session.h"
#include "mtcs/store/run_store.h"
#include "cli/stored_run.h"
#include "support/scratch_file.h"
#include "support/paths.h"

using namespace mtcs;
namespace fs = std::filesystem;

namespace {

// The plate scored by wall distances (fast), and its bundled hand-made layout.
const std::string kMold = MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml";
const std::string kLayout = MTCS_SOURCE_DIR + "/molds/plate.layout.yaml";

fs::path scratch(const std::string& name) { return mtcs_test::fresh_scratch_dir("start_layout", name); }

run::OptimizeRequest request(const fs::path& out, const std::string& algorithm, long evaluations) {
  run::OptimizeRequest r;
  r.mold = kMold;
  r.out = out.string();
  r.overrides.algorithm = algorithm;
  r.overrides.seed = 4;
  r.overrides.evaluations = evaluations;
  r.prepare_out = [](const std::string& dir) { fs::create_directories(dir); };
  r.start = {kLayout};
  return r;
}

run::OptimizeResult optimize(const run::OptimizeRequest& r, const std::function<bool()>& stop = {}) {
  return run::optimize_mold(r, [](const run::MoldOptimizer&, int) { return run::ProgressSink(); }, stop);
}

}  // namespace

TEST_CASE("optimize --start: the layout is in generation 0 as encoded, and the ES ends no worse than it",
          "[run][start]") {
  const run::Session session(kMold);
  const opt::Genotype start = session.problem().encode(session.read_layout(kLayout));
  const opt::Score start_score = session.problem().evaluate(start);
  REQUIRE(start_score.feasible);

  const fs::path dir = scratch("es");
  const run::OptimizeResult done = optimize(request(dir, "es", 1200));
  REQUIRE_FALSE(done.interrupted);
  const auto db = store::RunStore::open((dir / "run.sqlite").string());
  CHECK(run::stored_start(db.meta(), "meta") == std::vector<opt::Genotype>{start});
  const auto first = db.generation(0);
  REQUIRE(first);
  CHECK(std::any_of(first->population.begin(), first->population.end(),
                    [&](const opt::Individual& m) { return m.x == start; }));
  // Plus selection: no stored generation's best is worse than the start.
  for (const auto& s : db.summaries()) CHECK(db.generation(s.index)->population.front().score.value <= start_score.value);

  // A run's folder starts from the layout it wrote.
  const fs::path again = scratch("es_from_run");
  auto from_run = request(again, "es", 100);
  from_run.start = {dir.string()};
  optimize(from_run);
  const opt::Genotype written = session.problem().encode(session.read_layout((dir / "best.layout.yaml").string()));
  CHECK(run::stored_start(store::RunStore::open((again / "run.sqlite").string()).meta(), "meta") ==
        std::vector<opt::Genotype>{written});

  // Without --start the same seed's generation 0 holds no such layout: the option did something.
  const fs::path plain = scratch("es_plain");
  auto r = request(plain, "es", 200);
  r.start.clear();
  optimize(r);
  const auto g0 = store::RunStore::open((plain / "run.sqlite").string()).generation(0);
  CHECK(std::none_of(g0->population.begin(), g0->population.end(), [&](const opt::Individual& m) { return m.x == start; }));
}

TEST_CASE("optimize --start: interrupted and resumed, the run ends as the uninterrupted one (ES and SMS-EMOA)",
          "[run][start]") {
  for (const std::string algorithm : {"es", "sms-emoa"}) {
    INFO(algorithm);
    const long budget = algorithm == "es" ? 900 : 400;
    const fs::path whole = scratch("whole_" + algorithm), parts = scratch("parts_" + algorithm);
    const run::OptimizeResult done = optimize(request(whole, algorithm, budget));
    REQUIRE_FALSE(done.interrupted);
    int calls = 0;
    const run::OptimizeResult stopped = optimize(request(parts, algorithm, budget), [&] { return ++calls > 2; });
    REQUIRE(stopped.interrupted);
    run::OptimizeRequest again;
    again.resume = parts.string();
    again.start = {kLayout};
    CHECK_THROWS_WITH(optimize(again), Catch::Contains("--start") && Catch::Contains("drop --start"));
    again.start.clear();
    const run::OptimizeResult resumed = optimize(again);
    CHECK(resumed.last_generation == done.last_generation);
    CHECK(mtcs_test::stored_rows(parts) == mtcs_test::stored_rows(whole));

    // What a replay or a report rebuilds the initial population and reference point from.
    const auto meta = store::RunStore::open((whole / "run.sqlite").string()).meta();
    const run::Session stored(mold::load_mold_spec(kMold), meta.at("config"), "config");
    CHECK(run::stored_start(meta, "meta") ==
          std::vector<opt::Genotype>{stored.problem().encode(stored.read_layout(kLayout))});
  }
}

TEST_CASE("optimize --start: a missing layout, or more than the population holds, is refused, nothing written",
          "[run][start]") {
  const fs::path dir = scratch("refused");
  auto r = request(dir, "es", 200);
  r.start = {(mtcs_test::scratch_dir("start_layout") / "missing.layout.yaml").string()};
  try {
    optimize(r);
    FAIL("a missing start layout was accepted");
  } catch (const io::InputError& e) {
    CHECK(e.file() == r.start[0]);
  }
  CHECK_FALSE(fs::exists(dir));

  r.start = std::vector<std::string>(11, kLayout);
  CHECK_THROWS_WITH(optimize(r), Catch::Contains("--start") && Catch::Contains("mu 10"));
  CHECK_FALSE(fs::exists(dir));
}
