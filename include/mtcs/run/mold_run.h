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

// The reference point in scaled objectives (objective / its scale): the config's (--ref), or
// one that fits the mold: twice the worst value of each objective over the initial population
// of the config's seed, `start` layouts included (a fixed 4 each left new molds' fronts outside
// it: hypervolume 0); 4 where that population has no finite value.
std::vector<double> scaled_reference(const RunConfig& config, const MoldProblem& problem,
                                     const mold::Objectives& objectives, const std::vector<opt::Genotype>& start = {});
// That rule on a given initial population (the ES's stored generation 0 is the same sample),
// with each objective's scale.
std::vector<double> scaled_reference_of(const opt::Generation& initial, const std::vector<double>& scales);
// How that reference point was chosen, for the outputs.
std::string reference_origin(const RunConfig& config);

class MoldOptimizer {
 public:
  // `start`: members of the initial population as given (mtcs optimize --start: a designer's
  // layouts, encoded); the rest are sampled.
  MoldOptimizer(const MoldProblem& problem, const mold::Scene& scene, const RunConfig& config,
                const std::vector<opt::Genotype>& start = {});

  bool pareto() const { return pareto_; }
  // SMS-EMOA's population size and reference point (raw objective units).
  int mu() const { return sms_.config().mu; }
  const opt::Point& raw_reference() const { return sms_.config().ref; }
  // The finite-volume cell (mm) the best layout is re-scored at (RunConfig::final_cell; 0: not).
  double final_cell() const { return final_cell_; }
  const std::string& reference_origin() const { return reference_origin_; }
  // Whether g has spent the budget.
  bool done(const opt::Generation& g) const { return pareto_ ? sms_.done(g) : es_.done(g); }
  long budget() const { return sms_.config().evaluations; }
  // The optimisers themselves (islands make one per island from their configs).
  const opt::EvolutionStrategy& es() const { return es_; }
  const opt::SmsEmoa& sms() const { return sms_; }
  // Hypervolumes are reported in scaled objectives (objective / its scale in the spec): the
  // scales, the reference point so scaled, and the hypervolume of a front of raw points.
  const std::vector<double>& scales() const { return scales_; }
  std::vector<double> scaled_reference() const;
  double scaled_hypervolume(const std::vector<opt::Point>& raw_front) const;
  double scaled_hypervolume(const std::vector<opt::Point>& raw_front, const std::vector<double>& scaled_ref) const;
  // The ES has no reference point of its own (it ranks by one weighted value) and samples no
  // extra population for one: its hypervolumes (replay's anytime trace, the report) take
  // scaled_reference_of its first generation. False with SMS-EMOA or a given --ref.
  bool reference_from_first_generation() const { return reference_from_first_generation_; }
  // From a stored generation (resume) or a fresh population to the budget; on_generation sees
  // every ES generation and every SMS-EMOA step. With `stop`, it ends early once stop() is true
  // at the end of a generation (SMS-EMOA: of mu steps, the generations the store keeps).
  opt::Generation run(const opt::Generation* start, const std::function<void(const opt::Generation&)>& on_generation,
                      const std::function<bool()>& stop = {}) const;

 private:
  static opt::EsConfig es_config(const mold::Scene& scene, const RunConfig& config, const std::vector<opt::Genotype>& start);
  static opt::SmsConfig sms_config(const MoldProblem& problem, const mold::Scene& scene, const RunConfig& config,
                                   const std::vector<opt::Genotype>& start);

  opt::EvolutionStrategy es_;
  opt::SmsEmoa sms_;
  bool pareto_;
  double final_cell_;
  std::vector<double> scales_;
  std::string reference_origin_;
  bool reference_from_first_generation_;
};

}  // namespace mtcs::run
