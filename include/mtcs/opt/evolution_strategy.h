#pragma once
// (mu/rho +, lambda) evolution strategy with log-normal self-adaptive step sizes (Schwefel):
// every offspring multiplies its parents' (geometric mean) step sizes by
// exp(tau0 N(0,1) + tau N_i(0,1)), then mutates with them. Each generation is a pure function of
// the previous one and the run's seed (per-individual generators), so a run resumed from any
// stored generation continues exactly as it would have.

#include <cstdint>
#include <functional>
#include <vector>

#include "mtcs/opt/population.h"
#include "mtcs/opt/problem.h"

namespace mtcs::opt {

struct EsConfig {
  int mu = 10;
  int lambda = 40;
  int rho = 2;               // parents per offspring
  bool plus = true;          // (mu + lambda): parents compete with their offspring
  bool recombination = true;
  long evaluations = 20000;  // budget, including the initial population
  std::uint64_t seed = 1;
  double min_step = 1e-300, max_step = 1e300;
  // Baseline: offspring are fresh samples (no inheritance); selection as configured.
  bool random_search = false;
  // Multi-fidelity: > 0: every offspring is scored by Problem::screen, and only the best
  // `survivors` of them are scored by Problem::evaluate and enter selection; the population
  // holds evaluate's scores only. 0: every offspring is evaluated.
  int survivors = 0;
};

class EvolutionStrategy {
 public:
  EvolutionStrategy(const Problem& problem, EsConfig config);

  Generation initial() const;
  Generation step(const Generation& previous) const;
  bool done(const Generation& g) const { return g.evaluations + config_.lambda > config_.evaluations; }
  const EsConfig& config() const { return config_; }

 private:
  // The offspring that survive screening, with evaluate's scores.
  std::vector<Individual> screened(std::vector<Individual>& offspring, const std::vector<Genotype>& xs) const;

  const Problem& problem_;
  EsConfig config_;
};

// Runs to the budget from `start` (or a fresh initial population), calling `on_generation`
// after each generation (for storage and progress), or until `stop` says so after a generation.
Generation run(const EvolutionStrategy& es, const Generation* start,
               const std::function<void(const Generation&)>& on_generation,
               const std::function<bool(const Generation&)>& stop = {});

}  // namespace mtcs::opt
