// Bores against the molded part: at least clearances.bore_cavity of steel between a bore and the
// cavity: the exact solid-cylinder distance with the clearance as upper bound, to the box of a
// primitive cavity (no mesh code) or through the BVH of a mesh cavity.

#include "mtcs/geometry/cylinder_box_distance.h"
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
        const auto d = geometry::distance(b.hole, *box_, {.upper_bound = margin});
        if (!d.bounded)
          add_clearance(out, "bore_cavity", {b.name(), "cavity"}, d.distance, margin, (d.on_cylinder + d.on_triangle) / 2);
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
