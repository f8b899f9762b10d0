#include "mtcs/run/progress_line.h"

#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <sstream>

#include "mtcs/opt/sms_emoa.h"

namespace mtcs::run {

namespace {

// A day: a run whose time left exceeds it is told so once (the budget is likely a slip).
constexpr double kLongRun = 86400;
// The rate is not judged before this many seconds (the first generations pay for start-up).
constexpr double kRateSettles = 3;

}  // namespace

std::string duration_text(double seconds) {
  char text[64];
  if (!(seconds < 365 * 86400.0)) return "more than a year";
  const double whole = std::round(seconds);  // so that 119.7 s reads "2 min 0 s", not "1 min 60 s"
  if (whole < 100) std::snprintf(text, sizeof text, "%.0f s", whole);
  else if (whole < 3600) std::snprintf(text, sizeof text, "%.0f min %.0f s", std::floor(whole / 60), std::fmod(whole, 60));
  else if (seconds < 2 * 86400) std::snprintf(text, sizeof text, "%.1f h", seconds / 3600);
  else std::snprintf(text, sizeof text, "%.0f days", seconds / 86400);
  return text;
}

std::string progress_line(const MoldOptimizer& optimizer, const opt::Generation& g, double seconds, long evaluations,
                          double recent_rate) {
  const double rate = recent_rate > 0 ? recent_rate : seconds > 0 ? double(evaluations) / seconds : 0;
  int feasible = 0;
  for (const auto& ind : g.population) feasible += ind.score.feasible;
  const double eta = rate > 0 ? double(optimizer.budget() - g.evaluations) / rate : 0;
  char search[120];
  if (optimizer.pareto()) {
    const auto front = opt::SmsEmoa::front(g);
    std::snprintf(search, sizeof search, "HV %.6g | front %zu", optimizer.scaled_hypervolume(front), front.size());
  } else {
    const opt::Score& best = g.population.front().score;
    std::snprintf(search, sizeof search, "best %.6g%s", best.value, best.feasible ? "" : " (infeasible)");
  }
  char line[240];
  std::snprintf(line, sizeof line, "gen %5d | %9ld evals | %8.0f evals/s | %s | feasible %3.0f%% | ETA %s", g.index,
                g.evaluations, rate, search, 100.0 * feasible / double(g.population.size()),
                rate > 0 ? duration_text(eta).c_str() : "unknown");
  return line;
}

std::string hypervolume_basis(const MoldOptimizer& optimizer, const std::vector<std::string>& names) {
  std::ostringstream s;
  s << "HV: hypervolume of the feasible front in scaled objectives (";
  const auto ref = optimizer.scaled_reference();
  for (std::size_t k = 0; k < names.size(); ++k)
    s << (k ? ", " : "") << names[k] << " / " << optimizer.scales()[k];
  s << "), reference point [";
  for (std::size_t k = 0; k < ref.size(); ++k) s << (k ? ", " : "") << ref[k];
  s << "]: " << optimizer.reference_origin();
  return s.str();
}

ProgressPrinter::ProgressPrinter(const MoldOptimizer& optimizer, int log_every)
    : optimizer_(&optimizer), quiet_(!spdlog::should_log(spdlog::level::info)), tty_(::isatty(2)), log_every_(log_every) {}

void ProgressPrinter::operator()(const opt::Generation& g, double seconds, long evaluations) const {
  // The rate since the session's half-way point (the last kept point before it); points are kept
  // 5 % apart in time, so a run of days keeps a few hundred.
  if (history_.empty() || seconds >= 1.05 * history_.back().first) history_.emplace_back(seconds, evaluations);
  std::pair<double, long> half{0, 0};
  for (const auto& point : history_) {
    if (point.first > seconds / 2) break;
    half = point;
  }
  const auto [s0, e0] = half;
  const double rate = seconds > s0 ? double(evaluations - e0) / (seconds - s0) : 0;
  const double left = rate > 0 ? double(optimizer_->budget() - g.evaluations) / rate : 0;
  if (!warned_ && seconds >= kRateSettles && left > kLongRun) {
    warned_ = true;
    spdlog::warn("at {:.0f} evaluations/s the budget of {} evaluations needs {} more: Ctrl-C stops the run with its best so "
                 "far (mtcs optimize --resume continues it); a smaller --evaluations ends sooner",
                 rate, optimizer_->budget(), duration_text(left));
  }
  // SMS-EMOA's generations are its stored steps, every mu.
  const int generation = optimizer_->pareto() ? g.index / optimizer_->mu() : g.index;
  if (!prints(generation)) return;
  print(generation, progress_line(*optimizer_, g, seconds, evaluations, rate));
}

bool ProgressPrinter::prints(int generation) const { return !quiet_ && (tty_ || generation % log_every_ == 0); }

void ProgressPrinter::print(int generation, const std::string& line) const {
  if (!prints(generation)) return;
  if (tty_) std::fprintf(stderr, "\r%s\033[K", line.c_str());
  else spdlog::info(line);
}

}  // namespace mtcs::run
