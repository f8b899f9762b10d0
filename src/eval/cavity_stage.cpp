// Bores against the molded part: at least clearances.bore_cavity of steel between a bore and the
// cavity. A box cavity is closed form (no mesh code; the capsule around the bore, conservative by
// at most the radius at the flat ends); a mesh cavity gets the exact solid-cylinder distance
// through its BVH, with the clearance as upper bound.

#include "mtcs/geometry/triangle_distance.h"
#include "mtcs/mesh/bvh.h"
#include "stages.h"

namespace mtcs::eval {
namespace {

class CavityStage final : public Stage {
 public:
  explicit CavityStage(const mold::Scene& scene)
      : box_(scene.spec().cavity->box), bvh_(scene.cavity_bvh()), margin_(scene.spec().clearances.bore_cavity) {}
  std::string name() const override { return box_ ? "bore_cavity_box" : "bore_cavity_mesh"; }
  void run(const mold::Layout& layout, Evaluation& out) const override {
    for (const mold::Bore& b : layout.bores) {
      const double margin = margin_.at(b.diameter);
      if (box_) {
        const double d = std::max(0.0, geometry::segment_box_distance(b.hole.p0, b.hole.p1, *box_) - b.hole.radius);
        add_clearance(out, "bore_cavity", {b.name(), "cavity"}, d, margin, (b.hole.p0 + b.hole.p1) / 2);
      } else {
        const auto c = mesh::cylinder_clearance(*bvh_, b.hole, margin);
        if (!c.bounded) add_clearance(out, "bore_cavity", {b.name(), "cavity"}, c.distance, margin, c.where());
      }
    }
  }

 private:
  std::optional<geometry::Box> box_;
  const mesh::TriangleBvh* bvh_;
  mold::Length margin_;
};

}  // namespace

std::unique_ptr<Stage> make_cavity_stage(const mold::Scene& scene) { return std::make_unique<CavityStage>(scene); }

}  // namespace mtcs::eval
