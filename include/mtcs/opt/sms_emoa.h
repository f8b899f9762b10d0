#pragma once
// SMS-EMOA (Beume, Naujoks & Emmerich 2007): a steady-state (mu + 1) algorithm. Each step makes
// one offspring (recombination of two random parents, then mutation) and removes one member of
// the worst non-dominated front: either the one dominated by most others, then by least
// exclusive hypervolume ("domcount-then-hv", the paper's rule for fronts after the first), or by
// least contribution alone ("hv-only"). Points are ranked by Problem::ranking: by default
// infeasible points come after every feasible one, ordered by violation (constrained
// domination); a penalty method ranks penalised objectives instead. Contributions use the given
// reference point.
//
// lambda > 1 (for expensive evaluations): each step makes lambda offspring from the same
// parents, evaluates them in parallel and removes lambda members one by one; with lambda = 1 it
// is the steady-state algorithm above. The fronts are kept between steps (src/opt/sms_fronts.h),
// updated as a point comes in or goes out.

#include <cstdint>
#include <functional>
#include <memory>
#include <vector>

#include "mtcs/opt/evolution_strategy.h"
#include "mtcs/opt/hypervolume.h"

namespace mtcs::opt {

struct SmsConfig {
  int mu = 100;
  long evaluations = 20000;
  bool moves_within_budget = true;  // as EsConfig's
  std::uint64_t seed = 1;
  Point ref;                     // reference point for the contributions (and the reported HV)
  bool domcount_then_hv = true;  // false: least contribution only
  int lambda = 1;                // offspring per step, evaluated in parallel
  std::vector<Genotype> start;   // members of the initial population as given; the rest sampled
};

class SmsEmoa {
 public:
  SmsEmoa(const Problem& problem, SmsConfig config);

  Generation initial() const;
  // One step: lambda offspring, lambda removals. The generation index counts steps.
  Generation step(const Generation& previous) const;
  // The same step on g itself (what run does: no copy of the population).
  void advance(Generation& g) const;
  bool done(const Generation& g) const { return g.evaluations >= config_.evaluations; }
  const SmsConfig& config() const { return config_; }

  // The feasible non-dominated points of a population (by the scores themselves, whatever the
  // ranking the search used), each once: members with equal objectives are one point of the front
  // (a converged ES population holds the same layout many times).
  static std::vector<Point> front(const Generation& g);

  // Island migration hooks (opt/migration.h): up to k members of the first front (by the
  // problem's ranking), largest exclusive hypervolume contribution first; and the population
  // with `arrivals` inserted, reduced back to its size one removal at a time as a step reduces.
  std::vector<Individual> emigrants(const Generation& g, int k) const;
  Generation immigrate(const Generation& g, const std::vector<Individual>& arrivals) const;

 private:
  struct Fronts;

  const Problem& problem_;
  SmsConfig config_;
  // The fronts of the last population stepped (checked against the population it is given).
  std::shared_ptr<Fronts> fronts_;
};

// Runs to the budget (or until `stop` says so after a step: an interruption the run resumes from).
Generation run(const SmsEmoa& algorithm, const Generation* start, const std::function<void(const Generation&)>& on_step,
               const std::function<bool(const Generation&)>& stop = {});

}  // namespace mtcs::opt
