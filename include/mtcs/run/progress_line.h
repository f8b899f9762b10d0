#pragma once
// The live line of `mtcs optimize`: generation, evaluations, rate and time left, and what the
// search has so far: the ES's best weighted objective, or SMS-EMOA's hypervolume (in scaled
// objectives, against the run's reference point) and front size. SMS-EMOA keeps no single
// "best": a scalar there would be one member of the front and may get worse as the front grows.

#include <string>
#include <utility>
#include <vector>

#include "mtcs/run/mold_run.h"

namespace mtcs::run {

// `seconds` and `evaluations` are this session's (a resumed run counts from its start);
// `recent_rate` (evaluations/s), when given, is the rate shown and the time left is reckoned at.
std::string progress_line(const MoldOptimizer& optimizer, const opt::Generation& g, double seconds, long evaluations,
                          double recent_rate = 0);

// "42 s", "3 min 20 s", "2.5 h", "41 days", "more than a year": the time left as a person reads it.
std::string duration_text(double seconds);

// Prints the live line: rewritten in place on a terminal, a log line every `log_every`
// generations otherwise, nothing below spdlog's info level.
// The rate is the recent one (over the last half of the session, at least the last generation):
// the first generations pay for start-up, and a rate since the start would put early times left
// several times too high. Once the time left is known to exceed a day, it warns once.
class ProgressPrinter {
 public:
  ProgressPrinter(const MoldOptimizer& optimizer, int log_every);
  void operator()(const opt::Generation& g, double seconds, long evaluations) const;
  // Any line (the islands'), by the same rules, for the run's `generation`.
  void print(int generation, const std::string& line) const;
  // Whether the line of the run's `generation` is printed (quiet, a log's every log_every-th).
  bool prints(int generation) const;

 private:
  const MoldOptimizer* optimizer_;
  bool quiet_, tty_;
  int log_every_;
  mutable std::vector<std::pair<double, long>> history_;  // (seconds, evaluations), 5 % apart in time
  mutable bool warned_ = false;
};

// Said once before the run: what the hypervolume on the live line is measured against.
std::string hypervolume_basis(const MoldOptimizer& optimizer, const std::vector<std::string>& objective_names);

}  // namespace mtcs::run
