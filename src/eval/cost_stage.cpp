// Manufacturing cost (shared/notes/mtcs_literature.md 7.4, f3): per hole a setup cost plus a
// cost per drilled mm that grows for deep holes, plus a cost per plug and per baffle or bubbler:
//   sum_holes [setup + per_mm L (1 + deep_factor max(0, L/D - 10))] + plug n_plugs + insert n_inserts.

#include <algorithm>

#include "stages.h"

namespace mtcs::eval {

double drilling_cost(const mold::Layout& layout, const mold::Objectives& o) {
  double cost = o.cost_plug * layout.plugs;
  for (const mold::Bore& b : layout.bores) {
    const double L = b.drilled_length;
    cost += o.cost_setup + o.cost_per_mm * L * (1 + o.cost_deep_factor * std::max(0.0, L / b.diameter - 10));
    if (is_blind(b.kind)) cost += o.cost_insert;
  }
  return cost;
}

namespace {

class CostStage final : public Stage {
 public:
  explicit CostStage(const mold::Scene& scene) : o_(scene.spec().objectives) {
    for (std::size_t k = 0; k < o_.use.size(); ++k)
      if (o_.use[k] == mold::Objective::Cost) slot_ = k;
  }
  std::string name() const override { return "cost"; }
  void run(const mold::Layout& layout, Evaluation& out) const override {
    out.objectives[slot_] = drilling_cost(layout, o_);
  }

 private:
  mold::Objectives o_;
  std::size_t slot_ = 0;
};

}  // namespace

std::unique_ptr<Stage> make_cost_stage(const mold::Scene& scene) { return std::make_unique<CostStage>(scene); }

}  // namespace mtcs::eval
