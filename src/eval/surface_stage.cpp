// Bores against the block's surface: a deep hole drilled too close to a face wanders towards
// it and may break through (shared/notes/mtcs_literature.md 1.2). The stretch next to the
// bore's own entry is exempt, and so is the far end of a through-bore, whose exit is the
// circuit's inlet or outlet: it meets the face by design.

#include <algorithm>
#include <cmath>

#include "stages.h"

namespace mtcs::eval {

namespace {

class SurfaceStage final : public Stage {
 public:
  explicit SurfaceStage(const mold::Scene& scene) : scene_(scene), margin_(scene.spec().clearances.bore_surface) {}
  std::string name() const override { return "bore_surface"; }
  void run(const mold::Layout& layout, Evaluation& out) const override {
    for (const mold::Bore& b : layout.bores) {
      // Far enough along the axis that the entry face itself is margin + r away.
      const double cosine = std::max(0.1, std::cos(b.entry_angle_deg * 3.14159265358979323846 / 180));
      const double skip = (margin_ + b.hole.radius) / cosine;
      const double d = scene_.surface_clearance(b.hole, skip, margin_, b.through ? skip : 0.0);
      if (d < margin_)
        add_clearance(out, ViolationKind::BoreSurface, {b.name(), "block"}, d, margin_,
                      scene_.surface_place(b.hole, skip, b.through ? skip : 0.0));
    }
  }

 private:
  const mold::Scene& scene_;
  double margin_;
};

// The inlet (where the circuit's first bore's flow starts) or outlet (where its last ends).
geometry::Vec3 port_place(const mold::Layout& layout, const mold::PortProblem& p) {
  const mold::Bore* first = nullptr;
  const mold::Bore* last = nullptr;
  for (const mold::Bore& b : layout.bores) {
    if (b.circuit != p.circuit) continue;
    if (!first) first = &b;
    last = &b;
  }
  if (!first) return geometry::Vec3::Zero();
  return p.inlet ? first->flow_start : last->flow_end;
}

// Drilling limits: depth/diameter ratio, entry face and angle, inlet/outlet faces.
class DrillingStage final : public Stage {
 public:
  explicit DrillingStage(const mold::Scene& scene) : drill_(scene.spec().drilling) {}
  std::string name() const override { return "drilling"; }
  void run(const mold::Layout& layout, Evaluation& out) const override {
    for (const mold::Bore& b : layout.bores) {
      const double ratio = b.drilled_length / b.diameter;
      if (ratio > drill_.max_depth_ratio)
        out.violations.push_back({ViolationKind::DepthRatio, {b.name()}, ratio, drill_.max_depth_ratio,
                                  (ratio - drill_.max_depth_ratio) / drill_.max_depth_ratio, b.hole.p1, {}});
      if (!b.entry_allowed)
        out.violations.push_back({ViolationKind::EntryFace, {b.name(), mold::to_string(b.entry_face)}, 0, 0, 1, b.hole.p0, {}});
      if (b.entry_angle_deg > drill_.max_angle_deg + 1e-9)
        out.violations.push_back({ViolationKind::EntryAngle, {b.name()}, b.entry_angle_deg, drill_.max_angle_deg,
                                  (b.entry_angle_deg - drill_.max_angle_deg) / std::max(1.0, drill_.max_angle_deg), b.hole.p0, {}});
    }
    for (const mold::PortProblem& p : layout.ports) {
      const std::string c = "c" + std::to_string(p.circuit);
      out.violations.push_back({p.inlet ? ViolationKind::InletFace : ViolationKind::OutletFace, {c}, p.off_face, 0, p.off_face, port_place(layout, p), {}});
    }
  }

 private:
  mold::Drilling drill_;
};

}  // namespace

std::unique_ptr<Stage> make_surface_stage(const mold::Scene& scene) { return std::make_unique<SurfaceStage>(scene); }
std::unique_ptr<Stage> make_drilling_stage(const mold::Scene& scene) { return std::make_unique<DrillingStage>(scene); }

}  // namespace mtcs::eval
