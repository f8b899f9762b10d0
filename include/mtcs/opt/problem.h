#pragma once
// What the optimisers see of a problem (DESIGN.md: opt knows nothing of molds): sample,
// mutate, recombine, evaluate. A genotype is a vector of reals whose layout the problem alone
// knows (fixed length for test functions; circuits of waypoints for molds).

#include <string>
#include <vector>

#include "mtcs/opt/rng.h"

namespace mtcs::opt {

using Genotype = std::vector<double>;

struct Score {
  std::vector<double> objectives;
  double violation = 0;  // 0 when feasible
  bool feasible = true;
  double value = 0;      // the scalarised objective (weighted sum + penalty term)
  std::string detail;    // the problem's words for what is violated (stored, not compared)
};

// Constrained order of scalar scores: feasible first, then less violation, then smaller value.
inline bool feasible_first(const Score& a, const Score& b) {
  if (a.feasible != b.feasible) return a.feasible;
  if (!a.feasible && a.violation != b.violation) return a.violation < b.violation;
  return a.value < b.value;
}

// Constrained domination, SMS-EMOA's order: feasible beats infeasible, less violation beats
// more, then Pareto (no worse in every objective, better in one).
inline bool constrained_dominates(const Score& a, const Score& b) {
  if (a.feasible != b.feasible) return a.feasible;
  if (!a.feasible) return a.violation < b.violation;
  bool strictly = false;
  for (std::size_t k = 0; k < a.objectives.size(); ++k) {
    if (a.objectives[k] > b.objectives[k]) return false;
    strictly = strictly || a.objectives[k] < b.objectives[k];
  }
  return strictly;
}

class Problem {
 public:
  virtual ~Problem() = default;

  virtual std::string name() const = 0;
  virtual Genotype sample(Rng& rng) const = 0;
  // How many step sizes the ES adapts for this genotype: 1 (one scale) or its length (one
  // per coordinate; what an ill-conditioned separable function needs).
  virtual std::size_t step_sizes(const Genotype& g) const { return g.size(); }
  // The number of continuous parameters the step sizes act on: it sets the learning rates.
  virtual std::size_t dimension(const Genotype& g) const { return g.size(); }
  // How many of the strategy parameters after the step sizes are rotation angles (Schwefel's
  // correlated mutations: n(n-1)/2 for n coordinates; 0 for none). Angles are adapted
  // additively (5 degrees), step sizes log-normally.
  virtual std::size_t rotation_angles(const Genotype&) const { return 0; }
  // Initial strategy parameters: step sizes, then angles.
  virtual std::vector<double> initial_steps(const Genotype& g) const = 0;
  // Gaussian moves with the given strategy parameters plus any structural moves; must keep g
  // valid. Returns the evaluations the move itself spent (a move that scores candidates, like
  // the mold problem's reach move): they count in the optimisers' budgets.
  virtual long mutate(Genotype& g, const std::vector<double>& steps, Rng& rng) const = 0;
  // mutate, spending at most `may_spend` evaluations (what the budget has left beyond the
  // offspring still to score): the optimisers call this one, so that a run never passes its
  // budget. The default: mutate (a problem whose moves spend nothing).
  virtual long mutate_within(Genotype& g, const std::vector<double>& steps, Rng& rng, long may_spend) const {
    (void)may_spend;
    return mutate(g, steps, rng);
  }
  // Recombination of two parents; the default takes the first.
  virtual Genotype recombine(const Genotype& a, const Genotype& b, Rng& rng) const;
  // Thread-safe.
  virtual Score evaluate(const Genotype& g) const = 0;
  // The score of g, or, where the problem sees before its objectives that g ranks behind `bar`
  // whatever they are, a score that ranks behind bar with the objectives left at +inf. An
  // optimiser passes the member an offspring must beat to be kept at all. The default is
  // evaluate itself. Thread-safe.
  virtual Score evaluate_unless_behind(const Genotype& g, const Score& bar) const {
    (void)bar;
    return evaluate(g);
  }
  // A cheaper, rougher score for screening offspring (multi-fidelity ES: EsConfig::survivors);
  // the default is evaluate itself. Thread-safe.
  virtual Score screen(const Genotype& g) const { return evaluate(g); }
  // screen, or a score behind `bar` where the problem sees that g ranks behind it whatever its
  // objectives (as evaluate_unless_behind). The default is screen itself. Thread-safe.
  virtual Score screen_unless_behind(const Genotype& g, const Score& bar) const {
    (void)bar;
    return screen(g);
  }
  // Strict weak order of scores; the default compares values.
  virtual bool better(const Score& a, const Score& b) const { return a.value < b.value; }
  // The score SMS-EMOA ranks by. The default is the score itself, ranked by constrained
  // domination (feasible first, then less violation, then Pareto); a problem with a penalty
  // method instead folds the violation into the objectives and calls every point feasible.
  virtual Score ranking(const Score& s) const { return s; }
};

}  // namespace mtcs::opt
