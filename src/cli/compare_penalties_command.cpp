// mtcs compare-penalties: optimises one mold with each penalty variant on the same seeds and
// budget, and compares what they find: the hypervolume of the final feasible front (median,
// IQR), the feasible share of the evaluated layouts per budget decile, the time per evaluation,
// and rank-sum tests between the variants. Runs go one after another (each may use every
// thread), so that their times compare.

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>
#include <tbb/global_control.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <memory>
#include <sstream>

#include "log.h"
#include "mtcs/cli/commands.h"
#include "mtcs/eval/pipeline.h"
#include "mtcs/io/input_error.h"
#include "mtcs/run/penalty_report.h"
#include "mtcs/run/penalty_run.h"
#include "output_folder.h"
#include "mtcs/report/python_plot.h"
#include "number_checks.h"

namespace mtcs::cli {
namespace {

namespace fs = std::filesystem;

struct ComparePenaltiesOptions {
  std::string mold, config, out = "penalty-comparison", algorithm = "sms-emoa";
  std::vector<std::string> variants{"constrained_domination", "static_linear", "static_quadratic", "death"};
  int seeds = 5;
  std::optional<long> evaluations;
  std::vector<double> ref;
  int threads = 0;
};

std::vector<mold::PenaltyVariant> parse_variants(const std::vector<std::string>& names) {
  if (names.empty()) throw option_error("--variants", "name at least one penalty variant");
  std::vector<mold::PenaltyVariant> out;
  for (const auto& n : names) {
    const auto v = mold::penalty_variant(n);
    if (!v) throw option_error("--variants", "unknown penalty variant '" + n + "': expected " + mold::kPenaltyVariantNames);
    if (std::find(out.begin(), out.end(), *v) != out.end())
      throw option_error("--variants", "'" + n + "' is named twice");
    out.push_back(*v);
  }
  return out;
}

int run_compare(const ComparePenaltiesOptions& o) {
  const std::vector<mold::PenaltyVariant> variants = parse_variants(o.variants);
  refuse_nonempty_folder(o.out);
  // One Scene for every variant: the variant is part of each run's config, not of the mold.
  const run::Session session(o.mold, {o.config, o.algorithm, o.ref, std::nullopt, o.evaluations});
  // One reference point for every variant and seed (derived from seed 1's initial population
  // unless given), so that their hypervolumes compare.
  run::RunConfig config = session.config();
  const std::vector<std::string>& names = session.objective_names();
  run::RunConfig first_seed = config;
  first_seed.es.seed = 1;
  config.ref = run::scaled_reference(first_seed, session.problem(), session.spec().objectives);
  const std::vector<double>& ref = config.ref;
  std::optional<tbb::global_control> limit;
  if (o.threads > 0) limit.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(o.threads));
  make_output_folder(o.out);

  const bool tty = ::isatty(2), progress = spdlog::should_log(spdlog::level::info);
  spdlog::debug("mold {}: {} surface samples; run config:\n{}", o.mold, session.pipeline().surface_samples(),
                config.to_yaml(names));
  const int total = int(variants.size()) * o.seeds;
  std::vector<run::PenaltyRun> runs;
  for (const mold::PenaltyVariant v : variants) {
    run::RunConfig variant_config = config;
    variant_config.penalty = v;
    for (int seed = 1; seed <= o.seeds; ++seed) {
      const int index = int(runs.size()) + 1;
      char head[160];
      std::snprintf(head, sizeof head, "[%d/%d] %s seed %d", index, total, mold::to_string(v).c_str(), seed);
      runs.push_back(run::run_with_penalty(session, variant_config, std::uint64_t(seed), ref, [&](int deciles) {
        if (progress && tty) std::fprintf(stderr, "\r%s: %d%%\033[K", head, 10 * deciles);
      }));
      const run::PenaltyRun& r = runs.back();
      if (progress && tty) std::fprintf(stderr, "\r");
      spdlog::info("{}: HV {:.6g} (front {}), {:.0f}% of evaluations feasible, {:.1f} us/evaluation", head, r.hypervolume,
                   r.front_size, 100.0 * double(r.feasible) / double(r.evaluations), 1e6 * r.seconds / double(r.evaluations));
    }
  }
  const fs::path out(o.out);
  const run::PenaltyComparison comparison{o.mold, o.config, o.algorithm, o.variants, o.seeds, config.es.evaluations,
                                         config.es.mu, ref};
  run::write_penalty_report(out, comparison, runs, names, session.spec());
  std::ostringstream plot_log;
  const bool plotted = report::render_plot("plot_penalties.py", {out.string()}, plot_log);
  if (!plot_log.str().empty()) spdlog::info(plot_log.str().substr(0, plot_log.str().size() - 1));
  spdlog::info("results in {}/: summary.md, runs.csv, feasible_share.csv, rank_tests.csv{}", out.string(),
               plotted ? ", penalties.png" : "");
  return 0;
}

}  // namespace

Command add_compare_penalties_command(CLI::App& app) {
  auto o = std::make_shared<ComparePenaltiesOptions>();
  CLI::App* sub = app.add_subcommand(
      "compare-penalties",
      "Compare constraint-handling (penalty) variants on one mold: every variant runs on seeds 1..K with\n"
      "the same budget and settings; for each, the hypervolume of the final feasible front (median, IQR;\n"
      "only feasible layouts count; scaled objectives, against --ref), the feasible share of the\n"
      "evaluated layouts per tenth of the budget, the time per evaluation, and Wilcoxon rank-sum tests\n"
      "between the variants. Results in DIR: summary.md, runs.csv, feasible_share.csv, rank_tests.csv,\n"
      "penalties.png (when /usr/bin/python3 has matplotlib). Same seeds, same numbers, whatever --threads.\n"
      "Variants: constrained_domination (feasible first, then less violation), static_linear and\n"
      "static_quadratic (the mold's penalty.weight x CV or CV^2 added to every scaled objective), death\n"
      "(an infeasible layout is worse than any feasible one, and no better than another infeasible one).");
  sub->footer(
      "Example (3 variants x 5 seeds x 3000 evaluations on the demo plate, a few minutes):\n"
      "  mtcs compare-penalties molds/plate.yaml --variants constrained_domination,static_quadratic,death \\\n"
      "      --seeds 5 --evaluations 3000 --out runs/penalties\n"
      "  then read runs/penalties/summary.md and look at runs/penalties/penalties.png");
  sub->add_option("mold", o->mold, "mold spec (YAML)")->required();
  sub->add_option("--variants", o->variants, "penalty variants, comma-separated: " + mold::kPenaltyVariantNames)
      ->delimiter(',')
      ->capture_default_str();
  sub->add_option("--seeds", o->seeds, "seeds 1..K for every variant")->check(whole_number(1, 1000))->capture_default_str();
  sub->add_option("--evaluations", o->evaluations, "evaluation budget per run (default: the config's)")
      ->check(whole_number(1, 2000000000));
  sub->add_option("--config", o->config, "run config (YAML, see configs/): population, mutation rates, ...");
  sub->add_option("--algorithm", o->algorithm, "sms-emoa (a Pareto front) or es (one weighted objective); "
                                               "overrides the config's")
      ->check(CLI::IsMember({"es", "sms-emoa"}))
      ->capture_default_str();
  sub->add_option("--ref", o->ref, "reference point in scaled objectives (objective / scale), r1,r2,...; default 4 each")
      ->delimiter(',');
  sub->add_option("--out", o->out, "output folder")->capture_default_str();
  sub->add_option("--threads", o->threads, "worker threads (default: all cores); results do not depend on it")
      ->check(CLI::Range(0, 1024));
  add_log_flags(sub);
  return {sub, [o] { return run_compare(*o); }};
}

}  // namespace mtcs::cli
