// Bores against the molded part: at least clearances.bore_cavity of steel between a bore and the
// cavity: the exact solid-cylinder distance with the clearance as upper bound, to the box of a
// primitive cavity (no mesh code), to the two triangles of a patch on a block face, or through
// the BVH of a mesh cavity.

#include "mtcs/geometry/cylinder_box_distance.h"
#include "mtcs/geometry/cylinder_triangle_distance.h"
#include "mtcs/mesh/bvh.h"
#include "exact_cache.h"
#include "stages.h"
#include "surface_samples.h"

namespace mtcs::eval {
namespace {

class CavityStage final : public Stage {
 public:
  explicit CavityStage(const mold::Scene& scene)
      : box_(scene.spec().cavity->box), bvh_(scene.cavity_bvh()), margin_(scene.spec().clearances.bore_cavity) {
    if (scene.spec().cavity->is_patch()) {
      const auto [i, j, k] = patch_axes(*box_);
      auto corner = [&, i = i, j = j](int a, int b) {
        geometry::Vec3 p = box_->min;
        p[i] = a ? box_->max[i] : box_->min[i], p[j] = b ? box_->max[j] : box_->min[j];
        return p;
      };
      patch_ = {geometry::Triangle{corner(0, 0), corner(1, 0), corner(1, 1)},
                geometry::Triangle{corner(0, 0), corner(1, 1), corner(0, 1)}};
      box_.reset();
    }
  }
  std::string name() const override {
    return !patch_.empty() ? "bore_cavity_patch" : box_ ? "bore_cavity_box" : "bore_cavity_mesh";
  }
  void run(const mold::Layout& layout, Evaluation& out) const override {
    for (const mold::Bore& b : layout.bores) {
      // The boxes farther apart than the margin: clear, and cheaper to tell than the cache's lookup.
      const double margin = margin_.at(b.diameter);
      if (box_ && geometry::box_distance_sq(cylinder_box(b.hole), *box_) > margin * margin) continue;
      const CachedClearance& c = cache_.get(hole_key(b.hole, b.diameter), [&] { return clearance(b); });
      if (!c.clear)
        add_clearance(out, ViolationKind::BoreCavity, {b.name(), "cavity"}, c.distance, margin,
                      c.on_bore, c.on_other);
    }
  }

 private:
  CachedClearance clearance(const mold::Bore& b) const {
    const double margin = margin_.at(b.diameter);
    if (!patch_.empty()) {
      geometry::TriangleDistanceResult best;
      best.bounded = true;
      best.distance = margin;
      for (const auto& t : patch_) {
        const auto d = geometry::distance(b.hole, t, {.upper_bound = margin});
        if (!d.bounded && (best.bounded || d.distance < best.distance)) best = d;
      }
      return {best.bounded, best.distance, best.on_cylinder, best.on_triangle};
    }
    if (box_) {
      const auto d = geometry::distance(b.hole, *box_, {.upper_bound = margin});
      return {d.bounded, d.distance, d.on_cylinder, d.on_triangle};
    }
    const auto c = mesh::cylinder_clearance(*bvh_, b.hole, margin);
    return {c.bounded, c.distance, c.on_cylinder, c.on_surface};
  }

  std::optional<geometry::Box> box_;
  std::vector<geometry::Triangle> patch_;  // a patch on a block face: its two triangles
  const mesh::TriangleBvh* bvh_;
  mold::Length margin_;
  ExactCache<HoleKey, CachedClearance> cache_{1 << 9};
};

}  // namespace

std::unique_ptr<Stage> make_cavity_stage(const mold::Scene& scene) { return std::make_unique<CavityStage>(scene); }

}  // namespace mtcs::eval
