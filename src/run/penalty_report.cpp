// The report of a penalty comparison: every run as CSV, the feasible share per tenth of the
// budget, the rank-sum tests between the variants, and summary.md that puts them together.

#include "mtcs/run/penalty_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "mtcs/io/atomic_file.h"
#include "mtcs/opt/rank_sum_test.h"

namespace mtcs::run {
namespace {

namespace fs = std::filesystem;

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

std::string command_line(const PenaltyComparison& o) {
  std::string s = "mtcs compare-penalties " + o.mold + " --variants ";
  for (std::size_t i = 0; i < o.variants.size(); ++i) s += (i ? "," : "") + o.variants[i];
  s += " --seeds " + std::to_string(o.seeds) + " --evaluations " + std::to_string(o.evaluations) + " --algorithm " +
       o.algorithm + " --ref " + joined(o.ref, ",");
  if (!o.config.empty()) s += " --config " + o.config;
  return s;
}

void write_csvs(const fs::path& out, const std::vector<PenaltyRun>& runs, const std::vector<double>& ref) {
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
      const Window& w = r.windows[d];
      share.stream() << r.variant << ',' << r.seed << ',' << d + 1 << ',' << w.from << ',' << w.to << ',' << w.evaluated
                     << ',' << w.feasible << ','
                     << fmt(w.evaluated ? double(w.feasible) / double(w.evaluated) : std::nan(""), 17) << '\n';
    }
  share.commit();
}

void write_summary(const fs::path& out, const PenaltyComparison& o, const std::vector<PenaltyRun>& runs,
                   const std::vector<std::string>& names, const mold::MoldSpec& spec) {
  const std::vector<double>& ref = o.ref;
  const long evaluations = o.evaluations;
  const int mu = o.mu;
  std::ostringstream md;
  md << "# Penalty variants on " << fs::path(o.mold).filename().string() << "\n\n`" << command_line(o)
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
    std::vector<std::vector<double>> share(kDeciles);
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

}  // namespace

void write_penalty_report(const std::filesystem::path& out, const PenaltyComparison& comparison,
                          const std::vector<PenaltyRun>& runs, const std::vector<std::string>& objective_names,
                          const mold::MoldSpec& spec) {
  write_csvs(out, runs, comparison.ref);
  write_summary(out, comparison, runs, objective_names, spec);
}

}  // namespace mtcs::run
