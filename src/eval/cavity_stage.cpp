// Bores against the molded part: at least clearances.bore_cavity of steel between a bore and the
// cavity: the exact solid-cylinder distance with the clearance as upper bound, to the box of a
// primitive cavity (no mesh code), to the two triangles of a patch on a block face, or through
// the BVH of a mesh cavity.

#include "mtcs/geometry/cylinder_box_distance.h"
#include "cavity_solid.h"
#include "exact_cache.h"
#include "stages.h"

namespace mtcs::eval {
namespace {

class CavityStage final : public Stage {
 public:
  explicit CavityStage(const mold::Scene& scene) : cavity_(scene), margin_(scene.spec().clearances.bore_cavity) {}
  std::string name() const override { return std::string("bore_cavity_") + cavity_.kind(); }
  void run(const mold::Layout& layout, Evaluation& out) const override {
    for (const mold::Bore& b : layout.bores) {
      // The boxes farther apart than the margin: clear, and cheaper to tell than the cache's lookup.
      const double margin = margin_.at(b.diameter);
      if (cavity_.box() && geometry::box_distance_sq(cylinder_box(b.hole), *cavity_.box()) > margin * margin) continue;
      const CachedClearance& c =
          cache_.get(hole_key(b.hole, b.diameter), [&] { return cavity_.distance(b.hole, margin); });
      if (!c.clear)
        add_clearance(out, ViolationKind::BoreCavity, {b.name(), "cavity"}, c.distance, margin,
                      c.on_bore, c.on_other);
    }
  }

 private:
  CavitySolid cavity_;
  mold::Length margin_;
  ExactCache<HoleKey, CachedClearance> cache_{1 << 9};
};

}  // namespace

std::unique_ptr<Stage> make_cavity_stage(const mold::Scene& scene) { return std::make_unique<CavityStage>(scene); }

}  // namespace mtcs::eval
