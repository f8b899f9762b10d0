// The `drillable` constraint: a bore's direction must lie in a free cell of the accessibility
// map at its entry (eval/drill_access.h). Its amount is the angle to the nearest free cell's
// centre in cell heights (180 / rows degrees), so a bore nearly drillable costs little.

#include "mtcs/eval/drill_access.h"
#include "stages.h"

namespace mtcs::eval {
namespace {

class DrillableStage final : public Stage {
 public:
  explicit DrillableStage(const DrillAccess& access) : access_(access) {}
  std::string name() const override { return "drillable"; }
  void run(const mold::Layout& layout, Evaluation& out) const override {
    const double cell_deg = 180.0 / access_.spec().rows;
    for (const mold::Bore& b : layout.bores) {
      const DrillVerdict v = access_.check(b);
      if (v.free) continue;
      out.violations.push_back({ViolationKind::Drillable, {b.name(), "cavity"}, v.angle_to_free_deg, 0,
                                std::max(v.angle_to_free_deg, 1e-9) / cell_deg, b.hole.p0, std::nullopt});
    }
  }

 private:
  const DrillAccess& access_;
};

}  // namespace

std::unique_ptr<Stage> make_drillable_stage(const DrillAccess& access) { return std::make_unique<DrillableStage>(access); }

}  // namespace mtcs::eval
