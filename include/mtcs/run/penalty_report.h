#pragma once
// What `mtcs compare-penalties` leaves in its folder: runs.csv, feasible_share.csv,
// rank_tests.csv and summary.md (the command line that made them, the hypervolume median and
// IQR per variant with the reference point, the feasible share per tenth, rank-sum tests).

#include <filesystem>
#include <string>
#include <vector>

#include "mtcs/mold/mold_spec.h"
#include "mtcs/run/penalty_run.h"

namespace mtcs::run {

// How the runs were made: what the summary states.
struct PenaltyComparison {
  std::string mold, config, algorithm;
  std::vector<std::string> variants;
  int seeds = 0;
  long evaluations = 0;
  int mu = 0;
  std::vector<double> ref;  // in scaled objectives
};

void write_penalty_report(const std::filesystem::path& out, const PenaltyComparison& comparison,
                          const std::vector<PenaltyRun>& runs, const std::vector<std::string>& objective_names,
                          const mold::MoldSpec& spec);

}  // namespace mtcs::run
