#pragma once
// The evaluation pipeline, assembled per scene from the stages it needs: a scene without a
// cavity mesh builds no mesh stage, one without keep-outs no keep-out stage, one whose
// objectives do not include the thermal proxies samples no surface.

#include <memory>
#include <string>
#include <vector>

#include "mtcs/eval/evaluation.h"
#include "mtcs/eval/temperature_objectives.h"
#include "mtcs/mold/genome.h"
#include "mtcs/mold/layout.h"
#include "mtcs/mold/scene.h"

namespace mtcs::eval {

class DrillAccess;

class Stage {
 public:
  virtual ~Stage() = default;
  virtual std::string name() const = 0;
  virtual void run(const mold::Layout& layout, Evaluation& out) const = 0;
};

// What a pipeline is built for: whole evaluations, or the constraints alone (a command that
// checks a layout's clearances builds no thermal model: seconds on the plate).
enum class PipelineScope { everything, constraints };

class Pipeline {
 public:
  // The temperature objectives ask the solver `temperatures` builds; by default the one of the
  // spec's thermal tier (eval/thermal_tiers.h). Tests and benchmarks may pass their own. With
  // PipelineScope::constraints no objective stage is built: the objectives stay 0.
  explicit Pipeline(const mold::Scene& scene, const TemperatureSolverFactory& temperatures = {},
                    PipelineScope scope = PipelineScope::everything);
  ~Pipeline();

  // Thread-safe: stages hold only data built at construction (and per-thread caches).
  Evaluation evaluate(const mold::Genome& genome, bool timed = false) const;
  Evaluation evaluate(const mold::Layout& layout, bool timed = false) const;
  // The constraint stages alone: the violations (and CV) of evaluate but ejectability (which
  // needs the temperatures), objectives left at 0. For
  // callers that ask only whether a layout is feasible (the reach move tries circuits alone):
  // the objective stages (the thermal proxies, the solver) are most of an evaluation's cost.
  Evaluation constraints(const mold::Layout& layout) const;
  // evaluate, but the objectives only for a feasible layout: an infeasible one gets its
  // geometric violations and their CV (not the eject verdict, which needs the solve) and every
  // objective at +inf, not computed. For optimisers that rank any infeasible layout behind the
  // feasible ones they hold.
  Evaluation evaluate_if_feasible(const mold::Genome& genome) const;

  std::vector<std::string> stage_names() const;
  std::vector<std::string> objective_names() const;
  std::size_t surface_samples() const { return samples_; }
  const mold::Scene& scene() const { return scene_; }
  // The accessibility maps of drilling.access_map (shared with AM-guided mutation), or null.
  const DrillAccess* drill_access() const { return drill_access_.get(); }

 private:
  void sum_violation(Evaluation& e) const;  // CV from the violations' amounts

  const mold::Scene& scene_;
  std::unique_ptr<DrillAccess> drill_access_;
  std::vector<std::unique_ptr<Stage>> stages_;  // the objective stages first, then the constraints
  std::size_t objective_stages_ = 0;
  std::size_t samples_ = 0;
};

}  // namespace mtcs::eval
