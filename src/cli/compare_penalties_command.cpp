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
#include "mtcs/io/atomic_file.h"
#include "mtcs/io/input_error.h"
#include "mtcs/opt/rank_sum_test.h"
#include "mtcs/run/penalty_run.h"
#include "output_folder.h"
#include "python_plot.h"
#include "number_checks.h"

namespace mtcs::cli {
namespace {

namespace fs = std::filesystem;

struct Options {
  std::string mold, config, out = "penalty-comparison", algorithm = "sms-emoa";
  std::vector<std::string> variants{"constrained_domination", "static_linear", "static_quadratic", "death"};
  int seeds = 5;
  std::optional<long> evaluations;
  std::vector<double> ref;
  int threads = 0;
};

std::string fmt(double v, int digits = 6) {
  if (std::isnan(v)) return "nan";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string joined(const std::vector<double>& v, const std::string& sep, int digits = 17) {
  std::string s;
  for (const double x : v) s += (s.empty() ? "" : sep) + fmt(x, digits);
  return s;
}

// Linear interpolation between order statistics (Hyndman & Fan type 7, numpy's default).
double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const double h = q * double(v.size() - 1);
  const auto lo = std::size_t(std::floor(h));
  return lo + 1 < v.size() ? v[lo] + (h - double(lo)) * (v[lo + 1] - v[lo]) : v[lo];
}

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

std::string command_line(const Options& o, const std::vector<double>& ref, long evaluations) {
  std::string s = "mtcs compare-penalties " + o.mold + " --variants ";
  for (std::size_t i = 0; i < o.variants.size(); ++i) s += (i ? "," : "") + o.variants[i];
  s += " --seeds " + std::to_string(o.seeds) + " --evaluations " + std::to_string(evaluations) + " --algorithm " +
       o.algorithm + " --ref " + joined(ref, ",");
  if (!o.config.empty()) s += " --config " + o.config;
  return s;
}

void write_csvs(const fs::path& out, const std::vector<run::PenaltyRun>& runs, const std::vector<double>& ref) {
  io::AtomicFile csv((out / "runs.csv").string());
  csv.stream() << "variant,seed,evaluations,hypervolume,front_size,feasible_share,seconds,us_per_evaluation,reference_point\n";
  for (const auto& r : runs)
    csv.stream() << r.variant << ',' << r.seed << ',' << r.evaluations << ',' << fmt(r.hypervolume, 17) << ','
                 << r.front_size << ',' << fmt(double(r.feasible) / double(r.evaluations), 17) << ','
                 << fmt(r.seconds) << ',' << fmt(1e6 * r.seconds / double(r.evaluations)) << ',' << joined(ref, " ")
                 << '\n';
  csv.commit();
  io::AtomicFile share((out / "feasible_share.csv").string());
  share.stream() << "variant,seed,decile,from,to,evaluated,feasible,share\n";
  for (const auto& r : runs)
    for (std::size_t d = 0; d < r.windows.size(); ++d) {
      const run::Window& w = r.windows[d];
      share.stream() << r.variant << ',' << r.seed << ',' << d + 1 << ',' << w.from << ',' << w.to << ',' << w.evaluated
                     << ',' << w.feasible << ','
                     << fmt(w.evaluated ? double(w.feasible) / double(w.evaluated) : std::nan(""), 17) << '\n';
    }
  share.commit();
}

void write_summary(const fs::path& out, const Options& o, const std::vector<run::PenaltyRun>& runs, const std::vector<double>& ref,
                   const std::vector<std::string>& names, const mold::MoldSpec& spec, long evaluations, int mu) {
  std::ostringstream md;
  md << "# Penalty variants on " << fs::path(o.mold).filename().string() << "\n\n`" << command_line(o, ref, evaluations)
     << "`\n\n" << o.algorithm << (o.algorithm == "sms-emoa" ? " (population " : " (mu ") << mu << "), seeds 1.." << o.seeds
     << ", " << evaluations << " evaluations per run.\n\nHV: hypervolume of the final population's feasible "
     << "non-dominated layouts (infeasible ones never count; 0 when a run ends without a feasible layout), in scaled "
     << "objectives (";
  for (std::size_t k = 0; k < names.size(); ++k)
    md << (k ? ", " : "") << names[k] << " / " << fmt(spec.objectives.scale(spec.objectives.use[k]));
  md << "), **reference point (" << joined(ref, ", ", 6) << ")**; a front beyond it in some objective adds 0. "
     << "IQR: first to third quartile (linear interpolation). "
     << "Feasible share: of the layouts evaluated in the first, middle (5th) and last tenth of the budget, median over "
     << "seeds.\n\n"
     << "| variant | median HV | IQR | runs: feasible front / HV > 0 | feasible share (1st / 5th / 10th tenth) | µs per evaluation (wall, selection included) |\n"
     << "|---|---:|---|---:|---|---:|\n";
  std::vector<std::vector<double>> hv_of;
  for (const auto& variant : o.variants) {
    std::vector<double> hv, us;
    std::vector<std::vector<double>> share(run::kDeciles);
    int with_front = 0, with_volume = 0;
    for (const auto& r : runs) {
      if (r.variant != variant) continue;
      hv.push_back(r.hypervolume);
      us.push_back(1e6 * r.seconds / double(r.evaluations));
      with_front += r.front_size > 0;
      with_volume += r.hypervolume > 0;
      for (std::size_t d = 0; d < r.windows.size(); ++d)
        if (r.windows[d].evaluated) share[d].push_back(double(r.windows[d].feasible) / double(r.windows[d].evaluated));
    }
    hv_of.push_back(hv);
    auto share_at = [&](int d) { return share[std::size_t(d)].empty() ? std::string("–") : fmt(100 * quantile(share[std::size_t(d)], 0.5), 3) + "%"; };
    md << "| " << variant << " | " << fmt(quantile(hv, 0.5)) << " | " << fmt(quantile(hv, 0.25)) << "–"
       << fmt(quantile(hv, 0.75)) << " | " << with_front << " / " << with_volume << " of " << hv.size() << " | " << share_at(0) << " / "
       << share_at(4) << " / " << share_at(9) << " | " << fmt(quantile(us, 0.5), 3) << " |\n";
  }
  md << "\nWilcoxon rank-sum (Mann–Whitney U) tests on the final HV, two-sided, each pair on its own (no "
        "multiple-testing correction). U counts the seeds' pairs where A's HV is above B's (ties 1/2).\n\n"
        "| A | B | U | p | method |\n|---|---|---:|---:|---|\n";
  io::AtomicFile tests((out / "rank_tests.csv").string());
  tests.stream() << "variant_a,variant_b,n_a,n_b,u,p,method\n";
  for (std::size_t a = 0; a < hv_of.size(); ++a)
    for (std::size_t b = a + 1; b < hv_of.size(); ++b) {
      const opt::RankSumTest t = opt::rank_sum_test(hv_of[a], hv_of[b]);
      const std::string method = t.exact ? "exact" : "normal approximation, tie-corrected";
      md << "| " << o.variants[a] << " | " << o.variants[b] << " | " << fmt(t.u) << " | " << fmt(t.p, 4) << " | "
         << method << " |\n";
      tests.stream() << o.variants[a] << ',' << o.variants[b] << ',' << hv_of[a].size() << ',' << hv_of[b].size() << ','
                     << fmt(t.u, 17) << ',' << fmt(t.p, 17) << ',' << (t.exact ? "exact" : "normal") << '\n';
    }
  tests.commit();
  md << "\nFiles: runs.csv (every run), feasible_share.csv (every tenth of every run), rank_tests.csv, penalties.png "
        "(scripts/plot_penalties.py DIR renders it).\n";
  io::AtomicFile summary((out / "summary.md").string());
  summary.stream() << md.str();
  summary.commit();
}

int run_compare(const Options& o) {
  const std::vector<mold::PenaltyVariant> variants = parse_variants(o.variants);
  refuse_nonempty_folder(o.out);
  // One Scene for every variant: the variant is part of each run's config, not of the mold.
  const run::Session session(o.mold, {o.config, o.algorithm, o.ref, std::nullopt, o.evaluations});
  const run::RunConfig& config = session.config();
  const std::vector<std::string>& names = session.objective_names();
  const std::vector<double> ref = run::scaled_reference(config, names.size());
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
  write_csvs(out, runs, ref);
  write_summary(out, o, runs, ref, names, session.spec(), config.es.evaluations, config.es.mu);
  std::ostringstream plot_log;
  const bool plotted = render_plot("plot_penalties.py", {out.string()}, plot_log);
  if (!plot_log.str().empty()) spdlog::info(plot_log.str().substr(0, plot_log.str().size() - 1));
  spdlog::info("results in {}/: summary.md, runs.csv, feasible_share.csv, rank_tests.csv{}", out.string(),
               plotted ? ", penalties.png" : "");
  return 0;
}

}  // namespace

Command add_compare_penalties_command(CLI::App& app) {
  auto o = std::make_shared<Options>();
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
