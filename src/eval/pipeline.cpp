#include "mtcs/eval/pipeline.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>

#include "mtcs/eval/drill_access.h"
#include "mtcs/eval/thermal_model.h"
#include "mtcs/eval/thermal_tiers.h"
#include "mtcs/mold/decoder.h"
#include "stages.h"

namespace mtcs::eval {

Pipeline::Pipeline(const mold::Scene& scene, const TemperatureSolverFactory& temperatures, PipelineScope scope)
    : scene_(scene) {
  const mold::MoldSpec& spec = scene.spec();
  // The objectives it builds stages for: none for the constraints alone.
  const std::vector<mold::Objective> none;
  const auto& use = scope == PipelineScope::everything ? spec.objectives.use : none;
  auto uses = [&](mold::Objective o) { return std::find(use.begin(), use.end(), o) != use.end(); };
  // Objectives.
  if ((uses(mold::Objective::Uniformity) || uses(mold::Objective::WorstCovered))) {
    if (!spec.cavity) throw std::invalid_argument("the thermal objectives need a cavity");
    SurfaceSamples samples = sample_cavity(*spec.cavity);
    samples_ = samples.size();
    stages_.push_back(make_thermal_stage(scene, std::move(samples)));
  }
  for (const mold::Objective o : use) {
    if (!mold::is_temperature_objective(o)) continue;
    if (!spec.cavity) throw std::invalid_argument("the temperature objectives need a cavity");
    thermal::Samples samples = thermal_samples(scene);
    samples_ = std::max(samples_, samples.size());
    stages_.push_back(make_temperature_stage(scene, temperatures ? temperatures : temperature_solver(spec.thermal.tier),
                                             std::move(samples)));
    break;
  }
  if (uses(mold::Objective::Cost)) stages_.push_back(make_cost_stage(scene));
  objective_stages_ = stages_.size();
  // Constraints: only those the scene has elements for.
  stages_.push_back(make_bore_bore_stage(scene));
  bool cylinders = false, meshes = false;
  for (const auto& k : spec.keep_outs) cylinders = cylinders || k.cylinder, meshes = meshes || k.mesh;
  if (cylinders) stages_.push_back(make_keep_out_cylinder_stage(scene));
  if (meshes) stages_.push_back(make_keep_out_mesh_stage(scene));
  if (spec.cavity) stages_.push_back(make_cavity_stage(scene));
  stages_.push_back(make_surface_stage(scene));
  stages_.push_back(make_drilling_stage(scene));
  if (spec.thermal.flowing()) stages_.push_back(make_coolant_stage(scene));
  if (spec.drilling.access_map) {
    drill_access_ = std::make_unique<DrillAccess>(scene);
    stages_.push_back(make_drillable_stage(*drill_access_));
  }
}

Pipeline::~Pipeline() = default;

Evaluation Pipeline::evaluate(const mold::Genome& genome, bool timed) const {
  const auto t0 = std::chrono::steady_clock::now();
  const mold::Layout layout = mold::decode(scene_, genome);
  const double decode_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  Evaluation e = evaluate(layout, timed);
  if (timed) e.stages.insert(e.stages.begin(), {"decode", decode_seconds});
  return e;
}

Evaluation Pipeline::evaluate(const mold::Layout& layout, bool timed) const {
  Evaluation e;
  e.objectives.assign(scene_.spec().objectives.use.size(), 0.0);
  for (const auto& stage : stages_) {
    if (!timed) {
      stage->run(layout, e);
      continue;
    }
    const auto t0 = std::chrono::steady_clock::now();
    stage->run(layout, e);
    e.stages.push_back({stage->name(), std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count()});
  }
  // A bore through the part has no meaningful temperature: a tier's out-of-bounds result counts
  // as its defect only on a layout that meets every geometric rule. Ejectability counts always
  // (dropped, it would let a layout escape it by breaking a clearance a little).
  const auto geometric = [](const Violation& v) { return is_geometric(v.kind); };
  if (std::any_of(e.violations.begin(), e.violations.end(), geometric))
    e.violations.erase(std::remove_if(e.violations.begin(), e.violations.end(),
                                      [](const Violation& v) { return v.kind == ViolationKind::TemperatureBounds; }),
                       e.violations.end());
  sum_violation(e);
  return e;
}

void Pipeline::sum_violation(Evaluation& e) const {
  e.violation = 0;
  for (const Violation& v : e.violations) e.violation += std::pow(v.amount, scene_.spec().penalty.power);
}

Evaluation Pipeline::constraints(const mold::Layout& layout) const {
  Evaluation e;
  e.objectives.assign(scene_.spec().objectives.use.size(), 0.0);
  for (std::size_t s = objective_stages_; s < stages_.size(); ++s) stages_[s]->run(layout, e);
  sum_violation(e);
  return e;
}

Evaluation Pipeline::evaluate_if_feasible(const mold::Genome& genome) const {
  const mold::Layout layout = mold::decode(scene_, genome);
  Evaluation e = constraints(layout);
  if (!e.feasible()) {
    std::fill(e.objectives.begin(), e.objectives.end(), std::numeric_limits<double>::infinity());
    return e;
  }
  // evaluate's result bit for bit for a layout that meets every geometric rule (the objective
  // stages add only the thermal verdicts, which evaluate lists first). An infeasible one lacks
  // its eject verdict here: the caller ranks it behind feasible layouts whatever its CV.
  for (std::size_t s = 0; s < objective_stages_; ++s) stages_[s]->run(layout, e);
  sum_violation(e);
  return e;
}

std::vector<std::string> Pipeline::stage_names() const {
  std::vector<std::string> names;
  for (const auto& s : stages_) names.push_back(s->name());
  return names;
}

std::vector<std::string> Pipeline::objective_names() const {
  std::vector<std::string> names;
  for (const auto o : scene_.spec().objectives.use) names.push_back(mold::to_string(o));
  return names;
}

}  // namespace mtcs::eval
