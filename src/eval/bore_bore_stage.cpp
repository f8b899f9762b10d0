// Bore-bore clearance: a sweep over the bores' boxes inflated by half the margin sends only the
// pairs that can be closer than the margin to the exact cylinder kernel, with the margin as its
// upper bound. Consecutive bores of a circuit meet by design and are skipped.

#include <algorithm>
#include <numeric>

#include "mtcs/geometry/cylinder_distance.h"
#include "exact_cache.h"
#include "stages.h"

namespace mtcs::eval {
namespace {

using geometry::Vec3;

class BoreBoreStage final : public Stage {
 public:
  explicit BoreBoreStage(const mold::Scene& scene) : margin_(scene.spec().clearances.bore_bore) {}
  std::string name() const override { return "bore_bore"; }

  void run(const mold::Layout& layout, Evaluation& out) const override {
    const std::size_t n = layout.bores.size();
    struct Item {
      Vec3 lo, hi;
      int index;
    };
    static thread_local std::vector<Item> items;  // per thread: no allocation per evaluation
    items.resize(n);
    const double pad = margin_ / 2;
    for (std::size_t i = 0; i < n; ++i) {
      const auto& c = layout.bores[i].hole;
      const Vec3 r = Vec3::Constant(c.radius + pad);
      items[i] = {c.p0.cwiseMin(c.p1) - r, c.p0.cwiseMax(c.p1) + r, int(i)};
    }
    std::sort(items.begin(), items.end(), [](const Item& a, const Item& b) { return a.lo.x() < b.lo.x(); });
    const geometry::DistanceRequest request{.upper_bound = margin_};
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 1; j < n && items[j].lo.x() <= items[i].hi.x(); ++j) {
        if ((items[j].lo.array() > items[i].hi.array()).any() || (items[i].lo.array() > items[j].hi.array()).any()) continue;
        const mold::Bore& a = layout.bores[std::size_t(items[i].index)];
        const mold::Bore& b = layout.bores[std::size_t(items[j].index)];
        if (a.circuit == b.circuit && std::abs(a.segment - b.segment) == 1) continue;  // junction
        const auto& d = cache_.get(pair_key(a.hole, b.hole), [&] {
          const auto r = geometry::distance(a.hole, b.hole, request);
          return CachedClearance{r.bounded, r.distance, r.witness_a, r.witness_b};
        });
        if (d.clear || d.distance >= margin_) continue;
        const bool ordered = items[i].index < items[j].index;
        add_clearance(out, ViolationKind::BoreBore, ordered ? std::vector{a.name(), b.name()} : std::vector{b.name(), a.name()},
                      d.distance, margin_, ordered ? d.on_bore : d.on_other, ordered ? d.on_other : d.on_bore);
      }
    }
  }

 private:
  double margin_;
  ExactCache<PairKey, CachedClearance> cache_{1 << 10};
};

}  // namespace

std::unique_ptr<Stage> make_bore_bore_stage(const mold::Scene& scene) { return std::make_unique<BoreBoreStage>(scene); }

void add_clearance(Evaluation& out, ViolationKind kind, std::vector<std::string> elements, double distance,
                   double margin, const geometry::Vec3& where) {
  if (!(distance < margin) || margin <= 0) return;
  Violation v;
  v.kind = kind;
  v.elements = std::move(elements);
  v.distance = distance;
  v.margin = margin;
  v.amount = (margin - distance) / margin;
  v.where = where;
  out.violations.push_back(std::move(v));
}

void add_clearance(Evaluation& out, ViolationKind kind, std::vector<std::string> elements, double distance,
                   double margin, const geometry::Vec3& on_first, const geometry::Vec3& on_second) {
  const std::size_t before = out.violations.size();
  add_clearance(out, kind, std::move(elements), distance, margin, (on_first + on_second) / 2);
  if (out.violations.size() > before) out.violations.back().closest = std::pair{on_first, on_second};
}

}  // namespace mtcs::eval
