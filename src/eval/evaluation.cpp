#include "mtcs/eval/evaluation.h"

#include <limits>

namespace mtcs::eval {

Fitness fitness(const Evaluation& e, const mold::MoldSpec& spec, const std::vector<double>& weights) {
  const auto& o = spec.objectives;
  double value = 0;
  for (std::size_t k = 0; k < e.objectives.size(); ++k) {
    value += (k < weights.size() ? weights[k] : 1.0) * e.objectives[k] / o.scale(o.use[k]);
  }
  Fitness f{e.feasible(), e.violation, value};
  switch (spec.penalty.variant) {
    case mold::PenaltyVariant::StaticLinear: f.value += spec.penalty.weight * e.violation; break;
    case mold::PenaltyVariant::StaticQuadratic: f.value += spec.penalty.weight * e.violation * e.violation; break;
    case mold::PenaltyVariant::Death:
      if (!f.feasible) f.value = std::numeric_limits<double>::infinity();
      break;
    case mold::PenaltyVariant::ConstrainedDomination: break;
  }
  return f;
}

bool better(const Fitness& a, const Fitness& b, mold::PenaltyVariant variant) {
  if (variant == mold::PenaltyVariant::ConstrainedDomination) {
    if (a.feasible != b.feasible) return a.feasible;
    if (!a.feasible && a.violation != b.violation) return a.violation < b.violation;
  }
  return a.value < b.value;
}

}  // namespace mtcs::eval
