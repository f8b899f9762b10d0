#include "mtcs/eval/evaluation.h"

#include <limits>

namespace mtcs::eval {

Fitness fitness(const Evaluation& e, const mold::MoldSpec& spec, const std::vector<double>& weights) {
  const auto& o = spec.objectives;
  double value = 0;
  for (std::size_t k = 0; k < e.objectives.size(); ++k) {
    value += (k < weights.size() ? weights[k] : 1.0) * e.objectives[k] / o.scale(o.use[k]);
  }
  return {e.feasible(), e.violation, value + penalty_term(e.feasible(), e.violation, spec.penalty)};
}

double penalty_term(bool feasible, double violation, const mold::Penalty& penalty) {
  switch (penalty.variant) {
    case mold::PenaltyVariant::StaticLinear: return penalty.weight * violation;
    case mold::PenaltyVariant::StaticQuadratic: return penalty.weight * violation * violation;
    case mold::PenaltyVariant::Death: return feasible ? 0 : std::numeric_limits<double>::infinity();
    case mold::PenaltyVariant::ConstrainedDomination: return 0;
  }
  return 0;
}

bool better(const Fitness& a, const Fitness& b, mold::PenaltyVariant variant) {
  if (variant == mold::PenaltyVariant::ConstrainedDomination) {
    if (a.feasible != b.feasible) return a.feasible;
    if (!a.feasible && a.violation != b.violation) return a.violation < b.violation;
  }
  return a.value < b.value;
}

}  // namespace mtcs::eval
