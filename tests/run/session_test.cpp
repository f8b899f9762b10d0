// The run module's Session: one Scene per command run (compare-penalties included, however many
// variants it compares), and the penalty variant as part of the run config, ranking exactly as a
// mold spec with that variant ranks.

#include <catch2/catch.hpp>

#include <CLI/CLI.hpp>
#include <tbb/global_control.h>
#include <filesystem>

#include "mtcs/cli/commands.h"
#include "mtcs/io/input_error.h"
#include "mtcs/opt/rng.h"
#include "mtcs/run/session.h"
#include "support/scratch_file.h"
#include "support/paths.h"

using namespace mtcs;

namespace {

// The plate scored by wall distances: these runs optimise, and the temperatures would make them ~50x slower.
const std::string kMold = MTCS_SOURCE_DIR + "/molds/plate_wall_distance.yaml";

// mtcs ARGS in this process, through the cli library (the command's own code path).
int run_in_process(std::vector<std::string> args) {
  CLI::App app{"mtcs"};
  const cli::Command command = cli::add_compare_penalties_command(app);
  std::vector<char*> argv{const_cast<char*>("mtcs")};
  for (auto& a : args) argv.push_back(a.data());
  app.parse(int(argv.size()), argv.data());
  return command.run();
}

}  // namespace

TEST_CASE("compare-penalties builds the Scene once for all its variants", "[run][session]") {
  const auto out = mtcs_test::fresh_scratch_dir("session", "compare");
  const long before = run::Session::scenes_built();
  REQUIRE(run_in_process({"compare-penalties", kMold, "--variants", "constrained_domination,static_linear,death",
                          "--seeds", "2", "--evaluations", "150", "--algorithm", "es", "--quiet", "--out",
                          out.string()}) == 0);
  CHECK(run::Session::scenes_built() - before == 1);
  CHECK(std::filesystem::exists(out / "runs.csv"));
  std::filesystem::remove_all(out);
}

TEST_CASE("the run config's penalty variant ranks as the spec's would", "[run][session][penalty]") {
  // Reference: the mold spec edited to the variant, its problem built on its own Scene.
  mold::MoldSpec edited = mold::load_mold_spec(kMold);
  const mold::PenaltyVariant spec_default = edited.penalty.variant;
  for (const auto variant : {mold::PenaltyVariant::StaticLinear, mold::PenaltyVariant::StaticQuadratic,
                             mold::PenaltyVariant::Death}) {
    REQUIRE(variant != spec_default);
    edited.penalty.variant = variant;
    const run::Session by_spec(edited, run::RunOverrides{});
    const run::Session by_config(mold::load_mold_spec(kMold), "penalty: " + mold::to_string(variant) + "\n", "test");
    REQUIRE(by_config.config().penalty == variant);
    CHECK(by_config.problem().penalty_variant() == variant);
    opt::Rng rng(7);
    for (int i = 0; i < 20; ++i) {
      const opt::Genotype g = by_spec.problem().sample(rng);
      const opt::Score a = by_spec.problem().evaluate(g), b = by_config.problem().evaluate(g);
      CHECK(a.value == b.value);  // NaN never: death's +inf compares equal
      const opt::Score ra = by_spec.problem().ranking(a), rb = by_config.problem().ranking(b);
      CHECK(ra.objectives == rb.objectives);
      CHECK(ra.feasible == rb.feasible);
    }
  }
}

TEST_CASE("run config: penalty is read, written back, and checked", "[run][session][penalty]") {
  const std::vector<std::string> names{"a", "b"};
  const run::RunConfig c = run::parse_run_config("penalty: static_quadratic\n", "cfg.yaml", names);
  REQUIRE(c.penalty == mold::PenaltyVariant::StaticQuadratic);
  CHECK(run::parse_run_config(c.to_yaml(names), "again", names).penalty == c.penalty);
  CHECK_FALSE(run::parse_run_config("seed: 3\n", "cfg.yaml", names).penalty.has_value());
  try {
    run::parse_run_config("seed: 3\npenalty: gentle\n", "cfg.yaml", names);
    FAIL("no error");
  } catch (const io::InputError& e) {
    const std::string what = e.what();
    CHECK(what.find("cfg.yaml:2:") != std::string::npos);
    CHECK(what.find("penalty") != std::string::npos);
  }
}

TEST_CASE("run config: a store made before the ES's restart resumes without it, today's runs restart after 200",
          "[run][session][restart]") {
  const std::vector<std::string> names{"a", "b"};
  const std::string before = "es: {mu: 10, lambda: 40, rho: 2, plus: true, recombination: true}\nseed: 3\n";
  CHECK(run::parse_run_config(before, "cfg.yaml", names).es.restart_after == 200);  // a new run's default
  CHECK(run::parse_stored_run_config(before, "run.sqlite:config", names).es.restart_after == 0);
  const run::RunConfig today = run::parse_run_config("seed: 3\n", "cfg.yaml", names);
  const run::RunConfig stored = run::parse_stored_run_config(today.to_yaml(names), "run.sqlite:config", names);
  CHECK(stored.es.restart_after == 200);
  CHECK(stored.es.restart == today.es.restart);
  CHECK(stored.es.restart_tolerance == today.es.restart_tolerance);
  run::RunConfig off = today;
  off.es.restart_after = 0;
  CHECK(run::parse_stored_run_config(off.to_yaml(names), "run.sqlite:config", names).es.restart_after == 0);
}

TEST_CASE("SMS-EMOA on the mold: same seed, same populations, with 1 thread or 2", "[run][sms-emoa][determinism]") {
  run::RunOverrides o;
  o.algorithm = "sms-emoa";
  o.seed = 4;
  o.evaluations = 160;
  const run::Session session(kMold, o);
  const run::MoldOptimizer optimizer(session.problem(), session.scene(), session.config());
  REQUIRE(optimizer.pareto());
  auto record = [&](int threads) {
    const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
    std::vector<std::vector<double>> log;
    optimizer.run(nullptr, [&](const opt::Generation& g) {
      for (const auto& ind : g.population) {
        log.push_back(ind.x);
        log.push_back(ind.score.objectives);
        log.push_back({ind.score.violation});
      }
    });
    return log;
  };
  CHECK(record(1) == record(2));
}

TEST_CASE("run config fidelity: a screen with its own wall images and samples scores as the spec that sets them",
          "[run][session][fidelity]") {
  const std::string plate = MTCS_SOURCE_DIR + "/molds/plate.yaml";
  const run::Session multi(mold::load_mold_spec(plate),
                           "fidelity: {screen: t2d, elements_per_bore: 2, wall_images: 1, sample_spacing: 22}\n", "test");
  mold::MoldSpec cheap = mold::load_mold_spec(plate);
  cheap.thermal.elements_per_bore = 2;
  cheap.thermal.wall_images = 1;
  cheap.thermal.sample_spacing = 22;
  const run::Session same(std::move(cheap), run::RunOverrides{});
  // Finer than the cavity's samples (5.5 mm) is the cavity's own, as in the spec.
  const run::Session fine(mold::load_mold_spec(plate), "fidelity: {screen: t2d, sample_spacing: 1}\n", "test");
  mold::MoldSpec cavity = mold::load_mold_spec(plate);
  cavity.thermal.sample_spacing = 5.5;
  const run::Session at_cavity(std::move(cavity), run::RunOverrides{});
  opt::Rng rng(5);
  int differ = 0;
  for (int i = 0; i < 6; ++i) {
    const opt::Genotype g = multi.problem().sample(rng);
    const opt::Score rough = multi.problem().screen(g), full = multi.problem().evaluate(g);
    CHECK(rough.objectives == same.problem().evaluate(g).objectives);
    CHECK(fine.problem().screen(g).objectives == at_cavity.problem().evaluate(g).objectives);
    differ += rough.objectives != full.objectives;
  }
  CHECK(differ == 6);
  const auto& names = multi.objective_names();
  const run::RunConfig again = run::parse_run_config(multi.config().to_yaml(names), "again", names);
  CHECK(again.screen_elements == 2);
  CHECK(again.screen_wall_images == 1);
  CHECK(again.screen_sample_spacing == 22);
  for (const std::string key : {"wall_images: 1", "sample_spacing: 22"}) {
    try {
      run::parse_run_config("fidelity: {" + key + "}\n", "cfg.yaml", names);
      FAIL("no error");
    } catch (const io::InputError& e) {
      CHECK(std::string(e.what()).find("needs fidelity.screen") != std::string::npos);
    }
  }
}

TEST_CASE("configs/es_screened.yaml: a T2 screen over 22 mm samples, 5 of 40 re-scored", "[run][session][fidelity]") {
  // What experiments/thermal/es_screen.md measured (its t2s5c arm); the file must keep saying it.
  const run::Session plate(MTCS_SOURCE_DIR + "/molds/plate.yaml");
  const run::RunConfig c = run::load_run_config(MTCS_SOURCE_DIR + "/configs/es_screened.yaml", plate.objective_names());
  CHECK(c.screen_tier == mold::ThermalTier::T2);
  CHECK(c.screen_elements == 2);
  CHECK(c.screen_wall_images == 0);
  CHECK(c.screen_sample_spacing == 22);
  CHECK(c.es.survivors == 5);
  CHECK(c.es.mu == 10);
  CHECK(c.es.lambda == 40);
  CHECK(c.es.plus);
}

TEST_CASE("run config fidelity: the screen scores by its tier, evaluate by the spec's", "[run][session][fidelity]") {
  const std::string block = MTCS_SOURCE_DIR + "/molds/thermal_block.yaml";
  const run::Session plain(mold::load_mold_spec(block), run::RunOverrides{});
  mold::MoldSpec t1_spec = mold::load_mold_spec(block);
  t1_spec.thermal.tier = mold::ThermalTier::T1;
  const run::Session t1(std::move(t1_spec), run::RunOverrides{});
  const run::Session multi(mold::load_mold_spec(block), "fidelity: {screen: t1, survivors: 7, final_cell: 3}\n", "test");
  REQUIRE(multi.config().es.survivors == 7);
  CHECK(multi.config().final_cell == 3);
  // Written back and read again: a resumed run screens the same way.
  const auto& names = multi.objective_names();
  const run::RunConfig again = run::parse_run_config(multi.config().to_yaml(names), "again", names);
  CHECK(again.screen_tier == mold::ThermalTier::T1);
  CHECK(again.es.survivors == 7);
  CHECK(again.final_cell == 3);
  opt::Rng rng(11);
  int differ = 0;
  for (int i = 0; i < 10; ++i) {
    const opt::Genotype g = plain.problem().sample(rng);
    const opt::Score full = multi.problem().evaluate(g), rough = multi.problem().screen(g);
    CHECK(full.objectives == plain.problem().evaluate(g).objectives);
    CHECK(rough.objectives == t1.problem().evaluate(g).objectives);
    differ += rough.objectives != full.objectives;
  }
  CHECK(differ == 10);
  CHECK(multi.problem().screened() == 10);
  try {
    run::parse_run_config("fidelity: {screen: fd}\n", "cfg.yaml", names);
    FAIL("no error");
  } catch (const io::InputError& e) {
    CHECK(std::string(e.what()).find("fidelity.screen") != std::string::npos);
  }
}
