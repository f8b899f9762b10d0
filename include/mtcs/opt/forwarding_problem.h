#pragma once
// A problem that passes every call to another: the base of wrappers that watch a problem (a
// recorder of every evaluation, a test's log of scores) and override only what they watch.
// evaluate_unless_behind, screen and screen_unless_behind keep Problem's defaults, which call
// this->evaluate: a wrapper that overrides evaluate sees every evaluation; one that wants the
// inner problem's skip or screen overrides those too.

#include "mtcs/opt/problem.h"

namespace mtcs::opt {

class ForwardingProblem : public Problem {
 public:
  explicit ForwardingProblem(const Problem& inner) : inner_(inner) {}

  std::string name() const override { return inner_.name(); }
  Genotype sample(Rng& rng) const override { return inner_.sample(rng); }
  std::size_t step_sizes(const Genotype& g) const override { return inner_.step_sizes(g); }
  std::size_t dimension(const Genotype& g) const override { return inner_.dimension(g); }
  std::size_t rotation_angles(const Genotype& g) const override { return inner_.rotation_angles(g); }
  std::vector<double> initial_steps(const Genotype& g) const override { return inner_.initial_steps(g); }
  long mutate(Genotype& g, const std::vector<double>& steps, Rng& rng) const override { return inner_.mutate(g, steps, rng); }
  long mutate_within(Genotype& g, const std::vector<double>& steps, Rng& rng, long may_spend) const override {
    return inner_.mutate_within(g, steps, rng, may_spend);
  }
  Genotype recombine(const Genotype& a, const Genotype& b, Rng& rng) const override { return inner_.recombine(a, b, rng); }
  Score evaluate(const Genotype& g) const override { return inner_.evaluate(g); }
  bool better(const Score& a, const Score& b) const override { return inner_.better(a, b); }
  Score ranking(const Score& s) const override { return inner_.ranking(s); }

 protected:
  const Problem& inner_;
};

}  // namespace mtcs::opt
