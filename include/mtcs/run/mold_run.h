#pragma once
// One optimisation run on a mold, as mtcs optimize and mtcs compare-penalties both make it: the
// run config resolved from RUN.yaml and the command line, and the chosen optimiser (the ES or
// SMS-EMOA) set up for the mold and run to its budget.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "mtcs/run/mold_problem.h"
#include "mtcs/mold/scene.h"
#include "mtcs/opt/sms_emoa.h"
#include "mtcs/run/run_config.h"

namespace mtcs::run {

// What the command line may change in a run config; unset fields keep the config's.
struct RunOverrides {
  std::string config;       // RUN.yaml, or "" for the defaults
  std::string algorithm;    // es or sms-emoa
  std::vector<double> ref;  // reference point in scaled objectives
  std::optional<std::uint64_t> seed;
  std::optional<long> evaluations;
};

// Throws io::InputError naming the field (e.g. "ref" without one value per objective).
RunConfig resolve_run_config(const RunOverrides& overrides, const std::vector<std::string>& objective_names);

// The reference point in scaled objectives (objective / its scale): the config's, or 4 each.
std::vector<double> scaled_reference(const RunConfig& config, std::size_t objectives);

class MoldOptimizer {
 public:
  MoldOptimizer(const MoldProblem& problem, const mold::Scene& scene, const RunConfig& config);

  bool pareto() const { return pareto_; }
  // SMS-EMOA's population size and reference point (raw objective units).
  int mu() const { return sms_.config().mu; }
  const opt::Point& raw_reference() const { return sms_.config().ref; }
  // The finite-volume cell (mm) the best layout is re-scored at (RunConfig::final_cell; 0: not).
  double final_cell() const { return final_cell_; }
  // From a stored generation (resume) or a fresh population to the budget; on_generation sees
  // every ES generation and every SMS-EMOA step.
  opt::Generation run(const opt::Generation* start, const std::function<void(const opt::Generation&)>& on_generation) const;

 private:
  static opt::EsConfig es_config(const mold::Scene& scene, const RunConfig& config);
  static opt::SmsConfig sms_config(const mold::Scene& scene, const RunConfig& config);

  opt::EvolutionStrategy es_;
  opt::SmsEmoa sms_;
  bool pareto_;
  double final_cell_;
};

}  // namespace mtcs::run
