#include "cavity_solid.h"

#include "mtcs/geometry/cylinder_box_distance.h"
#include "mtcs/geometry/cylinder_triangle_distance.h"
#include "surface_samples.h"

namespace mtcs::eval {

CavitySolid::CavitySolid(const mold::Scene& scene) : box_(scene.spec().cavity->box), bvh_(scene.cavity_bvh()) {
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

const char* CavitySolid::kind() const { return !patch_.empty() ? "patch" : box_ ? "box" : "mesh"; }

CachedClearance CavitySolid::distance(const geometry::Cylinder& hole, double bound) const {
  if (!patch_.empty()) {
    geometry::TriangleDistanceResult best;
    best.bounded = true;
    best.distance = bound;
    for (const auto& t : patch_) {
      const auto d = geometry::distance(hole, t, {.upper_bound = bound});
      if (!d.bounded && (best.bounded || d.distance < best.distance)) best = d;
    }
    return {best.bounded, best.distance, best.on_cylinder, best.on_triangle};
  }
  if (box_) {
    const auto d = geometry::distance(hole, *box_, {.upper_bound = bound});
    return {d.bounded, d.distance, d.on_cylinder, d.on_triangle};
  }
  const auto c = mesh::cylinder_clearance(*bvh_, hole, bound);
  return {c.bounded, c.distance, c.on_cylinder, c.on_surface};
}

}  // namespace mtcs::eval
