#pragma once
// The live line of `mtcs optimize`: generation, evaluations, rate and time left, and what the
// search has so far: the ES's best weighted objective, or SMS-EMOA's hypervolume (in scaled
// objectives, against the run's reference point) and front size. SMS-EMOA keeps no single
// "best": a scalar there would be one member of the front and may get worse as the front grows.

#include <string>

#include "mtcs/run/mold_run.h"

namespace mtcs::run {

// `seconds` and `evaluations` are this session's (a resumed run counts from its start).
std::string progress_line(const MoldOptimizer& optimizer, const opt::Generation& g, double seconds, long evaluations);

// Prints the live line: rewritten in place on a terminal, a log line every `log_every`
// generations otherwise, nothing below spdlog's info level.
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
};

// Said once before the run: what the hypervolume on the live line is measured against.
std::string hypervolume_basis(const MoldOptimizer& optimizer, const std::vector<std::string>& objective_names);

}  // namespace mtcs::run
