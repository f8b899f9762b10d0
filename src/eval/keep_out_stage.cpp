// Bores against keep-outs (ejector pins, bolts, inserts), each with its own clearance:
// cylinders through the exact cylinder kernel, meshes through their BVH.

#include "mtcs/geometry/cylinder_distance.h"
#include "mtcs/mesh/bvh.h"
#include "exact_cache.h"
#include "stages.h"

namespace mtcs::eval {
namespace {

class KeepOutCylinderStage final : public Stage {
 public:
  explicit KeepOutCylinderStage(const mold::Scene& scene) {
    for (const auto& k : scene.spec().keep_outs) {
      if (!k.cylinder) continue;
      keep_outs_.push_back(k);
      // The keep-out's box grown by its clearance: a bore box that misses it is clear.
      boxes_.push_back(cylinder_box(*k.cylinder, k.clearance));
    }
  }
  std::string name() const override { return "bore_keepout_cylinders"; }
  void run(const mold::Layout& layout, Evaluation& out) const override {
    for (const mold::Bore& b : layout.bores) {
      if (!near_any(cylinder_box(b.hole))) continue;  // most bores: cheaper than the cache's lookup
      for (const auto& [i, c] : cache_.get(hole_key(b.hole, b.diameter), [&] { return shortfalls(b); }))
        add_clearance(out, ViolationKind::BoreKeepout, {b.name(), keep_outs_[i].name}, c.distance,
                      keep_outs_[i].clearance, c.on_bore, c.on_other);
    }
  }

 private:
  // Does a hole's box meet keep-out i's box grown by its clearance?
  bool near(const geometry::Box& hole, std::size_t i) const {
    return !(geometry::box_distance_sq(hole, boxes_[i]) > 0);  // touching counts; so does NaN, as before
  }
  bool near_any(const geometry::Box& hole) const {
    for (std::size_t i = 0; i < boxes_.size(); ++i)
      if (near(hole, i)) return true;
    return false;
  }

  // The keep-outs closer to the bore than their clearance, in keep-out order.
  std::vector<std::pair<std::size_t, CachedClearance>> shortfalls(const mold::Bore& b) const {
    std::vector<std::pair<std::size_t, CachedClearance>> out;
    const geometry::Box hole = cylinder_box(b.hole);
    for (std::size_t i = 0; i < keep_outs_.size(); ++i) {
      if (!near(hole, i)) continue;
      const auto& k = keep_outs_[i];
      const auto d = geometry::distance(b.hole, *k.cylinder, {.upper_bound = k.clearance});
      if (!d.bounded) out.push_back({i, {false, d.distance, d.witness_a, d.witness_b}});
    }
    return out;
  }

  std::vector<mold::KeepOut> keep_outs_;
  std::vector<geometry::Box> boxes_;
  ExactCache<HoleKey, std::vector<std::pair<std::size_t, CachedClearance>>> cache_{1 << 9};
};

class KeepOutMeshStage final : public Stage {
 public:
  explicit KeepOutMeshStage(const mold::Scene& scene) : scene_(scene) {
    for (std::size_t k = 0; k < scene.spec().keep_outs.size(); ++k)
      if (scene.spec().keep_outs[k].mesh) indices_.push_back(k);
  }
  std::string name() const override { return "bore_keepout_meshes"; }
  void run(const mold::Layout& layout, Evaluation& out) const override {
    for (const mold::Bore& b : layout.bores)
      for (const auto& [k, c] : cache_.get(hole_key(b.hole, b.diameter), [&] { return shortfalls(b); })) {
        const auto& spec = scene_.spec().keep_outs[k];
        add_clearance(out, ViolationKind::BoreKeepout, {b.name(), spec.name}, c.distance, spec.clearance, c.on_bore,
                      c.on_other);
      }
  }

 private:
  std::vector<std::pair<std::size_t, CachedClearance>> shortfalls(const mold::Bore& b) const {
    std::vector<std::pair<std::size_t, CachedClearance>> out;
    for (const std::size_t k : indices_) {
      const auto c = mesh::cylinder_clearance(*scene_.keep_out_bvh(k), b.hole, scene_.spec().keep_outs[k].clearance);
      if (!c.bounded) out.push_back({k, {false, c.distance, c.on_cylinder, c.on_surface}});
    }
    return out;
  }

  const mold::Scene& scene_;
  std::vector<std::size_t> indices_;
  ExactCache<HoleKey, std::vector<std::pair<std::size_t, CachedClearance>>> cache_{1 << 9};
};

}  // namespace

std::unique_ptr<Stage> make_keep_out_cylinder_stage(const mold::Scene& scene) {
  return std::make_unique<KeepOutCylinderStage>(scene);
}
std::unique_ptr<Stage> make_keep_out_mesh_stage(const mold::Scene& scene) {
  return std::make_unique<KeepOutMeshStage>(scene);
}

}  // namespace mtcs::eval
