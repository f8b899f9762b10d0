#pragma once
// (mu/rho +, lambda) evolution strategy with log-normal self-adaptive step sizes (Schwefel):
// every offspring multiplies its parents' (geometric mean) step sizes by
// exp(tau0 N(0,1) + tau N_i(0,1)), then mutates with them. Each generation is a pure function of
// the previous one and the run's seed (per-individual generators), so a run resumed from any
// stored generation continues exactly as it would have.
//
// Restart on stall: Generation::stalled counts the generations since the best last improved by
// more than `restart_tolerance` (relative); each time it reaches a multiple of `restart_after`,
// the ES restarts. `population` (an elitist restart): the best stays, every other member is
// replaced by a fresh sample (their evaluations count in the budget), and until the best
// improves again the best is no parent (plus strategies), so the fresh members evolve on their own instead of
// being displaced by the best's offspring: a new run of restart_after generations, the best
// kept; the rest ends as soon as any member leads it. A comma strategy drops the kept best at
// its next selection, and with mu = 1 there is nothing to replace: there a population restart
// keeps only the count. `steps`: every member's step sizes go back to their initial values (a local restart
// around the same members). The decisions read only the previous generation, so they are the
// same with any thread count and after a resume.

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
  // Whether the evaluations the moves spend (Problem::mutate_within) fit in the budget too: a
  // move that could pass it is not made. Off: on top of it (the islands of an archipelago).
  bool moves_within_budget = true;
  std::uint64_t seed = 1;
  double min_step = 1e-300, max_step = 1e300;
  // Baseline: offspring are fresh samples (no inheritance); selection as configured.
  bool random_search = false;
  // Multi-fidelity: > 0: every offspring is scored by Problem::screen, and only the best
  // `survivors` of them are scored by Problem::evaluate and enter selection; the population
  // holds evaluate's scores only. 0: every offspring is evaluated.
  int survivors = 0;
  // Restart on stall (above): generations without improvement of the best before a restart;
  // 0: never.
  int restart_after = 0;
  double restart_tolerance = 1e-3;  // relative: smaller gains of the best count as a stall
  enum class Restart { steps, population };
  Restart restart = Restart::population;
  // Members of the initial population as given (a designer's layouts to improve on); the rest
  // of its mu are sampled.
  std::vector<Genotype> start;
};

class EvolutionStrategy {
 public:
  EvolutionStrategy(const Problem& problem, EsConfig config);

  Generation initial() const;
  Generation step(const Generation& previous) const;
  // The next generation would pass the budget (its offspring, and a restart's fresh members).
  bool done(const Generation& g) const {
    const long fresh = restarts_after(g) && config_.restart == EsConfig::Restart::population
                           ? long(g.population.size()) - 1
                           : 0;
    return g.evaluations + fresh + config_.lambda > config_.evaluations;
  }
  const EsConfig& config() const { return config_; }
  // An island's arrivals (opt/migration.h, replace_worst). An arrival that leads as a gain of the
  // best would (restart_tolerance; any lead during a rest) resets the stall count: the island's
  // new best is a parent, and no restart discards it as converged.
  Generation immigrate(const Generation& g, const std::vector<Individual>& arrivals) const;
  // Whether the generation after `g` starts from a restarted population.
  bool restarts_after(const Generation& g) const {
    return config_.restart_after > 0 && g.stalled > 0 && g.stalled % config_.restart_after == 0;
  }
  // Whether the best of `g` is no parent of the next generation (a population restart's run).
  bool best_rests(const Generation& g) const {
    return config_.restart == EsConfig::Restart::population && config_.plus && config_.restart_after > 0 &&
           g.stalled >= config_.restart_after && g.population.size() > 1;
  }

 private:
  // The population the generation after `prev` starts from: prev's, or its restart (above);
  // adds the restart's evaluations to `evaluations`.
  std::vector<Individual> restarted(const Generation& prev, long& evaluations) const;
  // Whether `next` improved on `prev`'s best by more than the restart's tolerance.
  bool improved(const Generation& next, const Generation& prev) const;
  // The offspring that survive screening, with evaluate's scores; with a `bar` (the worst parent
  // of a plus strategy), screened and scored by the problem's *_unless_behind.
  std::vector<Individual> screened(std::vector<Individual>& offspring, const std::vector<Genotype>& xs,
                                   const Score* bar) const;

  const Problem& problem_;
  EsConfig config_;
};

// Runs to the budget from `start` (or a fresh initial population), calling `on_generation`
// after each generation (for storage and progress), or until `stop` says so after a generation.
Generation run(const EvolutionStrategy& es, const Generation* start,
               const std::function<void(const Generation&)>& on_generation,
               const std::function<bool(const Generation&)>& stop = {});

}  // namespace mtcs::opt
