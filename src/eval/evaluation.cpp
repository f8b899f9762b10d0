#include "mtcs/eval/evaluation.h"

#include <limits>

namespace mtcs::eval {

const char* to_string(ViolationKind kind) {
  switch (kind) {
    case ViolationKind::BoreBore: return "bore_bore";
    case ViolationKind::BoreKeepout: return "bore_keepout";
    case ViolationKind::BoreCavity: return "bore_cavity";
    case ViolationKind::BoreSurface: return "bore_surface";
    case ViolationKind::DepthRatio: return "depth_ratio";
    case ViolationKind::EntryFace: return "entry_face";
    case ViolationKind::EntryAngle: return "entry_angle";
    case ViolationKind::InletFace: return "inlet_face";
    case ViolationKind::OutletFace: return "outlet_face";
    case ViolationKind::Drillable: return "drillable";
    case ViolationKind::Eject: return "eject";
    case ViolationKind::TemperatureBounds: return "temperature_bounds";
    case ViolationKind::CoolantReynolds: return "coolant_reynolds";
    case ViolationKind::CoolantPressure: return "coolant_pressure";
    case ViolationKind::CoolantRise: return "coolant_rise";
    case ViolationKind::CoolantBalance: return "coolant_balance";
  }
  return "unknown";
}

bool is_thermal_verdict(ViolationKind kind) {
  return kind == ViolationKind::Eject || kind == ViolationKind::TemperatureBounds || kind == ViolationKind::CoolantRise ||
         kind == ViolationKind::CoolantBalance;
}

bool is_geometric(ViolationKind kind) {
  return !is_thermal_verdict(kind) && kind != ViolationKind::CoolantReynolds && kind != ViolationKind::CoolantPressure;
}

double scalar_fitness(const Evaluation& e, const mold::MoldSpec& spec, const std::vector<double>& weights) {
  const auto& o = spec.objectives;
  double value = 0;
  for (std::size_t k = 0; k < e.objectives.size(); ++k) {
    value += (k < weights.size() ? weights[k] : 1.0) * e.objectives[k] / o.scale(o.use[k]);
  }
  return value + penalty_term(e.feasible(), e.violation, spec.penalty);
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

}  // namespace mtcs::eval
