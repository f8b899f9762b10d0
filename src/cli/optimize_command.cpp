// mtcs optimize: the main job. Evolves bore layouts for a mold with the ES, evaluating each
// generation in parallel, storing every generation in DIR/run.sqlite (resumable after any
// interruption), and writing the best layout for CAD and for re-scoring.

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>

#include "log.h"
#include "mtcs/cli/commands.h"
#include "mtcs/io/input_error.h"
#include "mtcs/opt/benchmark_problems.h"
#include "mtcs/run/interruption.h"
#include "mtcs/run/islands.h"
#include "mtcs/run/optimize_run.h"
#include "mtcs/run/progress_line.h"
#include "mtcs/run/test_problem_run.h"
#include "option_error.h"
#include "output_folder.h"
#include "number_checks.h"

namespace mtcs::cli {
namespace {

namespace fs = std::filesystem;

struct OptimizeOptions {
  std::string mold, config, out = "mtcs-run", resume;
  std::optional<std::uint64_t> seed;
  std::optional<long> evaluations;
  int threads = 0;
  int polish = 0;  // COBYLA evaluations after the ES (0: none)
  std::string problem;    // a built-in test problem instead of a mold
  std::string algorithm = "es";
  std::vector<double> ref;
  bool json = false;
  run::IslandSettings islands;  // islands 0: one population
  std::string topology = "ring";
  std::vector<std::string> start;  // layouts the first population starts from
};

// A built-in multi-objective test problem with SMS-EMOA: prints a JSON summary, and stores the
// population every mu steps when --out is given.
int run_test_problem(const OptimizeOptions& o) {
  if (o.algorithm != "sms-emoa") throw option_error("--algorithm", "test problems run with --algorithm sms-emoa");
  if (!o.start.empty()) throw option_error("--start", "a mold's layout; test problems start from samples");
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
  std::cout << run::to_json(r, o.json) << "\n";
  return 0;
}

int run_optimize(const OptimizeOptions& o) {
  std::optional<tbb::global_control> limit;
  if (const int threads = o.threads > 0 ? o.threads : run::threads_per_rank(); threads > 0)
    limit.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
  run::OptimizeRequest request{o.mold, o.resume, o.out,
                               {o.config, o.algorithm == "es" ? "" : o.algorithm, o.ref, o.seed, o.evaluations}, o.polish,
                               [](const std::string& dir) { make_output_folder(dir); }, o.islands, o.start};
  request.islands.topology = opt::parse_topology(o.topology);
  run::Interruption interruption("\nmtcs optimize: interrupted before the search began: nothing was written\n");
  request.on_ready = [&] { interruption.begin_run(); };  // Ctrl-C then stops after a generation, resumable
  const run::OptimizeResult r = run::optimize_mold(
      request, [](const run::MoldOptimizer& optimizer, int log_every) { return run::ProgressSink(run::ProgressPrinter(optimizer, log_every)); },
      [&] { return interruption.requested(); });
  if (spdlog::should_log(spdlog::level::info) && ::isatty(2)) std::fprintf(stderr, "\n");
  if (!r.interrupted) return 0;
  // Said whatever the log level: the run is not finished.
  std::fprintf(stderr, "interrupted after generation %d (%ld of %ld evaluations): the best layout so far is in %s/\n"
                       "continue with: mtcs optimize --resume %s\n",
               r.last_generation, r.evaluations, r.budget, r.out_dir.c_str(), r.out_dir.c_str());
  return interruption.exit_code();
}

}  // namespace

Command add_optimize_command(CLI::App& app) {
  auto o = std::make_shared<OptimizeOptions>();
  CLI::App* sub = app.add_subcommand(
      "optimize",
      "Optimise the cooling bores of a mold: the evolution strategy (one weighted objective) or\n"
      "SMS-EMOA (--algorithm sms-emoa: a Pareto front, front.csv), or SMS-EMOA on a test problem.\n"
      "Every generation is stored in DIR/run.sqlite; an interrupted run (even kill -9) continues\n"
      "with --resume DIR and ends exactly as an uninterrupted one. Results in DIR: run.sqlite,\n"
      "best.layout.yaml (coordinates to 0.01 mm; edit and re-score with mtcs evaluate), bores.csv,\n"
      "holes.csv (the hole table: entry, direction, diameter, depth, plug, mm), bores.stl, summary.json.\n"
      "Ctrl-C finishes the current generation, writes these and prints the --resume command.\n"
      "Example: mtcs optimize molds/plate.yaml --config configs/es_default.yaml --out runs/plate --seed 1");
  sub->add_option("mold", o->mold, "mold spec (YAML)");
  sub->add_option("--config", o->config, "run config (YAML, see configs/)");
  sub->add_option("--out", o->out, "output folder")->capture_default_str();
  // The ranges of the run config's seed and evaluations (run_config.cpp).
  sub->add_option("--seed", o->seed, "random seed (overrides the config)")->check(whole_number(0, 9007199254740992));
  sub->add_option("--evaluations", o->evaluations, "evaluation budget (overrides the config)")
      ->check(whole_number(1, 2000000000));
  sub->add_option("--threads", o->threads,
                  "worker threads (default: all cores; under mpirun the cores / ranks on the machine); results do"
                  " not depend on it")
      ->check(CLI::Range(0, 1024));
  add_log_flags(sub);
  sub->add_option("--resume", o->resume, "continue the run stored in this folder");
  sub->add_option("--polish", o->polish,
                  "then refine the best layout's hole coordinates with NLopt's COBYLA for this many evaluations")
      ->check(CLI::Range(0, 10000000));
  sub->add_option("--start", o->start, "begin from this layout (LAYOUT.yaml or a run's folder: its best.layout.yaml),\n"
                  "the rest of the first population sampled; repeatable. The ES keeps it until a better one replaces it");
  sub->add_option("--problem", o->problem, "a built-in test problem instead of a mold: zdt1-4, zdt6, dtlz1-7");
  sub->add_option("--algorithm", o->algorithm,
                  "es (one weighted objective) or sms-emoa (a Pareto front; writes front.csv)")->capture_default_str()
      ->check(CLI::IsMember({"es", "sms-emoa"}));
  sub->add_option("--ref", o->ref,
                  "SMS-EMOA reference point, r1,r2,...: test problems 1.1 each; molds in scaled objectives\n"
                  "(objective / scale), default twice the worst of the initial population")
      ->delimiter(',');
  sub->add_flag("--json", o->json, "test problems: the summary as one line of JSON");
  sub->add_option("--islands", o->islands.islands,
                  "P populations (each 1/P of the budget) with migration, in threads, or one per rank under\n"
                  "mpirun -np P; the same seed and P give the same run either way")->check(CLI::Range(1, 65536));
  sub->add_option("--migration-every", o->islands.migration_every, "islands: generations between migrations")
      ->capture_default_str()->check(CLI::Range(1, 100000000));
  sub->add_option("--migrants", o->islands.migrants, "islands: members each island sends (ES: its best; SMS-EMOA: front\n"
                  "members of largest hypervolume contribution)")->capture_default_str()->check(CLI::Range(0, 100000));
  sub->add_option("--migration-delay", o->islands.migration_delay, "islands: migrations between a send and its\n"
                  "arrival (0: in lockstep); ranks wait only for migrants this old")->capture_default_str()
      ->check(CLI::Range(0, 1000));
  sub->add_option("--topology", o->topology, "islands: ring or fully-connected")->capture_default_str()
      ->check(CLI::IsMember({"ring", "fully-connected"}));
  return {sub, [o] {
            if (!o->problem.empty()) return run_test_problem(*o);
            if (o->resume.empty() && o->mold.empty())
              throw option_error("MOLD", "give a mold spec, or --resume DIR");
            return run_optimize(*o);
          }};
}

}  // namespace mtcs::cli
