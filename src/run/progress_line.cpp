#include "mtcs/run/progress_line.h"

#include <spdlog/spdlog.h>
#include <unistd.h>

#include <cstdio>
#include <sstream>

#include "mtcs/opt/sms_emoa.h"

namespace mtcs::run {

std::string progress_line(const MoldOptimizer& optimizer, const opt::Generation& g, double seconds, long evaluations) {
  const double rate = seconds > 0 ? double(evaluations) / seconds : 0;
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
  std::snprintf(line, sizeof line, "gen %5d | %9ld evals | %8.0f evals/s | %s | feasible %3.0f%% | ETA %.0f s", g.index,
                g.evaluations, rate, search, 100.0 * feasible / double(g.population.size()), eta);
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
  // SMS-EMOA's generations are its stored steps, every mu.
  const int generation = optimizer_->pareto() ? g.index / optimizer_->mu() : g.index;
  if (!prints(generation)) return;
  print(generation, progress_line(*optimizer_, g, seconds, evaluations));
}

bool ProgressPrinter::prints(int generation) const { return !quiet_ && (tty_ || generation % log_every_ == 0); }

void ProgressPrinter::print(int generation, const std::string& line) const {
  if (!prints(generation)) return;
  if (tty_) std::fprintf(stderr, "\r%s\033[K", line.c_str());
  else spdlog::info(line);
}

}  // namespace mtcs::run
