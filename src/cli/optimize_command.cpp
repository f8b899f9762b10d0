// mtcs optimize: the main job. Evolves bore layouts for a mold with the ES, evaluating each
// generation in parallel, storing every generation in DIR/run.sqlite (resumable after any
// interruption), and writing the best layout for CAD and for re-scoring.

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <sstream>

#include "log.h"
#include "mtcs/cli/commands.h"
#include "mtcs/eval/pipeline.h"
#include "mtcs/io/atomic_file.h"
#include "mtcs/io/input_error.h"
#include "mtcs/mold/decoder.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/opt/benchmark_problems.h"
#include "mtcs/store/run_store.h"
#include "mtcs/run/polish.h"
#include "mtcs/run/run_outputs.h"
#include "mtcs/run/run_record.h"
#include "mtcs/run/session.h"
#include "mtcs/run/stored_run.h"
#include "mtcs/run/test_problem_run.h"
#include "option_error.h"
#include "output_folder.h"
#include "number_checks.h"

namespace mtcs::cli {
namespace {

namespace fs = std::filesystem;

struct Options {
  std::string mold, config, out = "mtcs-run", resume;
  std::optional<std::uint64_t> seed;
  std::optional<long> evaluations;
  int threads = 0;
  int polish = 0;  // COBYLA evaluations after the ES (0: none)
  std::string problem;    // a built-in test problem instead of a mold
  std::string algorithm = "es";
  std::vector<double> ref;
  bool json = false;
};

// A built-in multi-objective test problem with SMS-EMOA: prints a JSON summary, and stores the
// population every mu steps when --out is given.
int run_test_problem(const Options& o) {
  if (o.algorithm != "sms-emoa") throw option_error("--algorithm", "test problems run with --algorithm sms-emoa");
  std::unique_ptr<opt::Problem> problem;
  try {
    problem = opt::make_benchmark_problem(o.problem);
  } catch (const std::invalid_argument& e) {
    throw option_error("--problem", e.what());
  }
  const std::vector<double> ref = o.ref.empty() ? run::default_test_reference(o.problem) : o.ref;
  if (ref.size() != run::default_test_reference(o.problem).size())
    throw option_error("--ref", "needs " + std::to_string(opt::objective_count(o.problem)) + " values");
  std::string store;
  if (!o.out.empty() && o.out != "mtcs-run") make_output_folder(o.out), store = (fs::path(o.out) / "run.sqlite").string();
  const run::TestProblemRun r =
      run::run_test_problem(*problem, o.problem, o.seed.value_or(1), o.evaluations.value_or(20000), ref, store);
  const nlohmann::ordered_json j{{"problem", r.problem},         {"algorithm", "sms-emoa"},  {"seed", r.seed},
                                 {"evaluations", r.evaluations}, {"hypervolume", r.hypervolume},
                                 {"reference_point", r.ref},     {"front_size", r.front_size}, {"seconds", r.seconds}};
  std::cout << (o.json ? j.dump() : j.dump(2)) << "\n";
  return 0;
}

// One status line on a terminal, a log line every few generations otherwise.
class Progress {
 public:
  Progress(int log_every, long budget)
      : quiet_(!spdlog::should_log(spdlog::level::info)), tty_(::isatty(2)), log_every_(log_every), budget_(budget) {}
  void operator()(const opt::Generation& g, double seconds, long evals_this_session) {
    if (quiet_) return;
    const double rate = seconds > 0 ? double(evals_this_session) / seconds : 0;
    int feasible = 0;
    for (const auto& ind : g.population) feasible += ind.score.feasible;
    const double eta = rate > 0 ? double(budget_ - g.evaluations) / rate : 0;
    char line[200];
    std::snprintf(line, sizeof line, "gen %5d | %9ld evals | %8.0f evals/s | best %.6g%s | feasible %3.0f%% | ETA %.0f s",
                  g.index, g.evaluations, rate, g.population.front().score.value,
                  g.population.front().score.feasible ? "" : " (infeasible)",
                  100.0 * feasible / double(g.population.size()), eta);
    if (tty_) std::fprintf(stderr, "\r%s\033[K", line);
    else if (g.index % log_every_ == 0) spdlog::info(line);
  }
  void done() const {
    if (!quiet_ && tty_) std::fprintf(stderr, "\n");
  }

 private:
  bool quiet_, tty_;
  int log_every_;
  long budget_;
};

int run_optimize(const Options& o) {
  std::string out_dir = o.resume.empty() ? o.out : o.resume;
  const std::string db_path = (fs::path(out_dir) / "run.sqlite").string();
  std::optional<store::RunStore> db;
  std::string mold_path = o.mold, config_text;
  std::map<std::string, std::string> meta;
  if (!o.resume.empty()) {
    if (!fs::exists(db_path)) throw io::InputError(db_path, 0, 0, "", "no run to resume here");
    db = store::RunStore::open(db_path);
    meta = db->meta();
    mold_path = meta.at("mold");
    config_text = meta.at("config");
  }
  if (!o.resume.empty() && run::content_hash(run::read_file_text(mold_path)) != meta.at("mold_hash"))
    throw io::InputError(mold_path, 0, 0, "", "the mold spec changed since the run started; start a new run");
  // A resumed run keeps its stored config; a new one resolves RUN.yaml and the command line.
  const run::RunOverrides overrides{o.config, o.algorithm == "es" ? "" : o.algorithm, o.ref, o.seed, o.evaluations};
  const run::Session session = o.resume.empty()
                                   ? run::Session(mold::load_mold_spec(mold_path), overrides)
                                   : run::Session(mold::load_mold_spec(mold_path), config_text, db_path + ":config");
  const mold::Scene& scene = session.scene();
  const std::vector<std::string>& names = session.objective_names();
  const run::RunConfig& config = session.config();
  if (o.resume.empty()) {
    make_output_folder(out_dir);
    if (fs::exists(db_path))
      throw io::InputError(db_path, 0, 0, "", "a run exists here: resume it with --resume " + out_dir + " or choose --out");
    meta = run::mold_run_meta(mold_path, session);
    db = store::RunStore::create(db_path, meta);
  }

  std::optional<tbb::global_control> limit;
  if (o.threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(o.threads));
  const run::MoldProblem& problem = session.problem();
  const run::MoldOptimizer optimizer(problem, scene, config);
  spdlog::debug("mold {}: {} surface samples; run config:\n{}", mold_path, session.pipeline().surface_samples(),
                config.to_yaml(names));
  Progress progress(config.log_every, config.es.evaluations);
  const run::StoredRun stored = run::run_stored(optimizer, problem, *db, progress);
  const opt::Generation& last = stored.last;
  const double seconds = stored.seconds;
  progress.done();

  // The best layout, for CAD and for re-scoring with mtcs evaluate; optionally polished.
  const opt::Individual& first = last.population.front();
  run::RunOutcome outcome{last, first.score, problem.genome(first.x), seconds, mold_path, std::nullopt, first.score.value};
  if (o.polish > 0) {
    outcome.polished = run::polish(problem, scene, outcome.genome, o.polish);
    if (outcome.polished->improved) outcome.genome = outcome.polished->genome, outcome.best = outcome.polished->score;
    spdlog::info("polish (COBYLA, {} evaluations): objective {:.6g}{}", outcome.polished->evaluations, outcome.best.value,
                 outcome.polished->improved ? "" : " (no improvement)");
  }
  const mold::Layout layout = run::write_run_outputs(out_dir, scene, optimizer, names, config.es.seed, outcome);
  const opt::Score& best = outcome.best;
  const mold::Genome& genome = outcome.genome;
  spdlog::info("{} best layout: {} bores in {} circuits, objective {:.6g}, {} evaluations in {:.6g} s",
               best.feasible ? "feasible" : "INFEASIBLE", layout.bores.size(), genome.circuits.size(),
               best.value, last.evaluations, seconds);
  spdlog::info("results in {}/: best.layout.yaml (mtcs evaluate {} --layout {}/best.layout.yaml), bores.csv, bores.stl, "
               "summary.json, run.sqlite",
               out_dir, mold_path, out_dir);
  return 0;
}

}  // namespace

Command add_optimize_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "optimize",
      "Optimise the cooling bores of a mold: the evolution strategy (one weighted objective) or\n"
      "SMS-EMOA (--algorithm sms-emoa: a Pareto front, front.csv), or SMS-EMOA on a test problem.\n"
      "Every generation is stored in DIR/run.sqlite; an interrupted run (even kill -9) continues\n"
      "with --resume DIR and ends exactly as an uninterrupted one. Results in DIR: run.sqlite,\n"
      "best.layout.yaml (edit and re-score with mtcs evaluate), bores.csv, bores.stl, summary.json.\n"
      "Example: mtcs optimize molds/plate.yaml --config configs/es_default.yaml --out runs/plate --seed 1");
  sub->add_option("mold", o->mold, "mold spec (YAML)");
  sub->add_option("--config", o->config, "run config (YAML, see configs/)");
  sub->add_option("--out", o->out, "output folder")->capture_default_str();
  // The ranges of the run config's seed and evaluations (run_config.cpp).
  sub->add_option("--seed", o->seed, "random seed (overrides the config)")->check(whole_number(0, 9007199254740992));
  sub->add_option("--evaluations", o->evaluations, "evaluation budget (overrides the config)")
      ->check(whole_number(1, 2000000000));
  sub->add_option("--threads", o->threads, "worker threads (default: all cores); results do not depend on it")
      ->check(CLI::Range(0, 1024));
  add_log_flags(sub);
  sub->add_option("--resume", o->resume, "continue the run stored in this folder");
  sub->add_option("--polish", o->polish,
                  "then refine the best layout's hole coordinates with NLopt's COBYLA for this many evaluations")
      ->check(CLI::Range(0, 10000000));
  sub->add_option("--problem", o->problem, "a built-in test problem instead of a mold: zdt1-4, zdt6, dtlz1-7");
  sub->add_option("--algorithm", o->algorithm,
                  "es (one weighted objective) or sms-emoa (a Pareto front; writes front.csv)")->capture_default_str()
      ->check(CLI::IsMember({"es", "sms-emoa"}));
  sub->add_option("--ref", o->ref,
                  "SMS-EMOA reference point, r1,r2,...: test problems 1.1 each; molds in scaled objectives, 4 each")
      ->delimiter(',');
  sub->add_flag("--json", o->json, "test problems: the summary as one line of JSON");
  return {sub, [o, sub] {
            if (!o->problem.empty()) return run_test_problem(*o);
            if (o->resume.empty() && o->mold.empty())
              throw option_error("MOLD", "give a mold spec, or --resume DIR");
            (void)sub;
            return run_optimize(*o);
          }};
}

}  // namespace mtcs::cli
