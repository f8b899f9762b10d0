#pragma once
// `mtcs optimize` on a mold, below the command line: opens a new run store or resumes one (the
// stored mold must be unchanged), runs the optimiser to its budget or to an interruption,
// polishes the best layout, rounds it for the shop and writes the run's outputs.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "mtcs/opt/population.h"
#include "mtcs/run/islands.h"
#include "mtcs/run/mold_run.h"

namespace mtcs::run {

struct OptimizeRequest {
  std::string mold;    // the spec of a new run
  std::string resume;  // or the folder of a stored run to continue
  std::string out;     // a new run's folder
  RunOverrides overrides;
  int polish = 0;      // COBYLA evaluations after the run (0: none)
  // Makes a new run's folder once the spec has loaded (the caller's rules for --out).
  std::function<void(const std::string& dir)> prepare_out;
  // A new run's islands (run/islands.h; islands 0: one population). Started by mpirun, one
  // island per rank: rank 0 writes the store and the outputs, the others only search.
  IslandSettings islands;
  // Layout files a new run's initial population starts from (--start); the rest is sampled.
  std::vector<std::string> start;
  // Called once the thermal model is built, before the store is made (until then nothing of the
  // run needs saving: Ctrl-C may end the program at once).
  std::function<void()> on_ready;
};

struct OptimizeResult {
  std::string out_dir, mold_path;
  bool interrupted = false;
  int last_generation = 0;
  long evaluations = 0, budget = 0;
};

// Called after each stored generation: generation, seconds so far, evaluations this session.
using ProgressSink = std::function<void(const opt::Generation&, double, long)>;
// Makes the sink once the optimiser exists (its kind and size shape the progress line).
using ProgressFactory = std::function<ProgressSink(const MoldOptimizer&, int log_every)>;

// Throws io::InputError for a run that cannot start or resume (named file and reason).
OptimizeResult optimize_mold(const OptimizeRequest& request, const ProgressFactory& progress,
                             const std::function<bool()>& stop);

}  // namespace mtcs::run
