#pragma once
// The stages of the pipeline, one file each; pipeline.cpp decides which a scene needs.

#include <memory>
#include <span>

#include "mtcs/eval/pipeline.h"
#include "mtcs/eval/temperature_objectives.h"
#include "mtcs/geometry/triangle_distance.h"
#include "mtcs/thermal/model.h"
#include "surface_samples.h"

namespace mtcs::eval {

std::unique_ptr<Stage> make_thermal_stage(const mold::Scene& scene, SurfaceSamples samples);
// Needs a cavity and a factory that builds a solver.
// samples: thermal_samples(scene) (drawn once: the local walls are ray casts).
std::unique_ptr<Stage> make_temperature_stage(const mold::Scene& scene, const TemperatureSolverFactory& factory,
                                              thermal::Samples samples);
std::unique_ptr<Stage> make_cost_stage(const mold::Scene& scene);
// The `cost` objective: drilling and plugging the layout's holes.
double drilling_cost(const mold::Layout& layout, const mold::Objectives& o);
std::unique_ptr<Stage> make_bore_bore_stage(const mold::Scene& scene);
std::unique_ptr<Stage> make_keep_out_cylinder_stage(const mold::Scene& scene);
std::unique_ptr<Stage> make_keep_out_mesh_stage(const mold::Scene& scene);
std::unique_ptr<Stage> make_cavity_stage(const mold::Scene& scene);
std::unique_ptr<Stage> make_surface_stage(const mold::Scene& scene);
std::unique_ptr<Stage> make_drilling_stage(const mold::Scene& scene);
class DrillAccess;
std::unique_ptr<Stage> make_drillable_stage(const DrillAccess& access);
// Each circuit's Reynolds number and pressure drop against the shop's limits (a flowing spec).
std::unique_ptr<Stage> make_coolant_stage(const mold::Scene& scene);
struct ShopCheck;
// Shop checks as violations of the circuit ("c2") at its inlet, the rise's at its outlet.
void add_shop_checks(Evaluation& out, std::span<const ShopCheck> checks, const mold::Layout& layout);

// The box of a cylinder grown by `grow` on every side: the clearance stages' cheap first test
// (geometry::box_distance_sq against the other element's box).
inline geometry::Box cylinder_box(const geometry::Cylinder& c, double grow = 0) {
  const geometry::Vec3 r = geometry::Vec3::Constant(c.radius + grow);
  return {c.p0.cwiseMin(c.p1) - r, c.p0.cwiseMax(c.p1) + r};
}

// A clearance shortfall as a violation; nothing when the distance meets the margin.
void add_clearance(Evaluation& out, ViolationKind kind, std::vector<std::string> elements, double distance,
                   double margin, const geometry::Vec3& where);
// The same with the closest points of the two elements (`where` is their midpoint).
void add_clearance(Evaluation& out, ViolationKind kind, std::vector<std::string> elements, double distance,
                   double margin, const geometry::Vec3& on_first, const geometry::Vec3& on_second);

}  // namespace mtcs::eval
