// The shop's limits on each circuit's coolant (issue 42, docs/coolant-circuits.md) as
// constraints: a Reynolds number below thermal.coolant.min_reynolds, a pressure drop above the
// supply. The coolant rise and the balance need the solve's heat: the temperature stage checks them.

#include <algorithm>

#include "mtcs/eval/circuit_hydraulics.h"
#include "stages.h"

namespace mtcs::eval {

void add_shop_checks(Evaluation& out, std::span<const ShopCheck> checks, const mold::Layout& layout) {
  for (const ShopCheck& c : checks) {
    // The circuit's inlet (its flow and drop), or its outlet (the warmest coolant).
    const bool rise = c.what == "rise";
    const mold::Bore* end = nullptr;  // the first bore in flow order, or the last for the rise
    for (const mold::Bore& b : layout.bores)
      if (b.circuit == c.circuit && (!end || (rise ? b.segment > end->segment : b.segment < end->segment))) end = &b;
    // A blind bore's coolant comes back out at its entry.
    const geometry::Vec3 where = !end                             ? geometry::Vec3::Zero()
                                 : rise && !is_blind(end->kind) ? end->flow_end
                                                                : end->flow_start;
    const ViolationKind kind = rise                    ? ViolationKind::CoolantRise
                               : c.what == "reynolds" ? ViolationKind::CoolantReynolds
                               : c.what == "balance"  ? ViolationKind::CoolantBalance
                                                      : ViolationKind::CoolantPressure;
    const double shortfall = std::abs(c.found - c.limit) / std::max(std::abs(c.limit), 1e-300);
    out.violations.push_back({kind, {"c" + std::to_string(c.circuit)}, c.found, c.limit, shortfall, where, {}});
  }
}

namespace {

class CoolantStage final : public Stage {
 public:
  explicit CoolantStage(const mold::Scene& scene) : spec_(scene.spec()) {}
  std::string name() const override { return "coolant"; }
  void run(const mold::Layout& layout, Evaluation& out) const override {
    add_shop_checks(out, coolant_circuits(layout, spec_).checks, layout);
  }

 private:
  const mold::MoldSpec& spec_;
};

}  // namespace

std::unique_ptr<Stage> make_coolant_stage(const mold::Scene& scene) { return std::make_unique<CoolantStage>(scene); }

}  // namespace mtcs::eval
