#pragma once
// The cavity-surface temperature of one layout, for people rather than the optimiser: what
// `mtcs thermal` prints and writes. The summary at the cavity samples (the numbers the
// temperature objectives use), the heat balance, temperatures at any points, and a field on a
// refined copy of the cavity surface for ParaView / MeshLab.

#include <string>
#include <vector>

#include "mtcs/eval/across_part.h"
#include "mtcs/eval/circuit_hydraulics.h"
#include "mtcs/eval/part_sides.h"
#include "mtcs/mesh/surface_field.h"
#include "mtcs/mold/layout.h"
#include "mtcs/mold/scene.h"
#include "mtcs/thermal/model.h"

namespace mtcs::eval {

struct ThermalQuery {
  mold::ThermalTier tier = mold::ThermalTier::T2d;
  int elements = 4;   // per bore, line sinks
  int wall_images = 2;  // reflection levels summed exactly at the walls, line sinks
  double cell = 2;    // mm, finite volumes
};
// The spec's tier and settings.
ThermalQuery thermal_query(const mold::MoldSpec& spec);

struct HeatBalance {
  double in = 0, to_channels = 0, to_faces = 0;  // W
  double residual() const { return in - to_channels - to_faces; }
};

// The cavity condition a solve used (thermal.cavity_condition), in the spec's SI units.
struct CavityConditionUsed {
  std::string model;              // coupled or flux
  double heat_flux = 0;           // W/m^2 (flux)
  double part_film = 0;           // W/(m^2 K) (coupled)
  double part_temperature = 0;    // degrees C (coupled)
  double in_mold = 0, cycle = 0;  // s, the nominal cycle the film is derived for (coupled)
  // mm, the part's wall: one value, or (cavity.wall_thickness: local) the thinnest and the
  // thickest place (samples and triangles); part_film is then the thickest triangle's, each
  // triangle of the cavity has its own.
  double wall_thinnest = 0, wall_thickest = 0;
  bool local_wall = false;
  double melt_temperature = 0;    // degrees C, thermal.polymer's: no steel can be hotter
};
CavityConditionUsed cavity_condition_used(const mold::MoldSpec& spec);

struct CavityTemperature {
  std::string tier;                  // t1, t2, t2d, fd
  CavityConditionUsed condition;
  std::string surface;               // thermal.objective_surface: heated or all
  thermal::Summary summary;          // area-weighted over the cavity samples (of that surface)
  geometry::Vec3 hottest;            // where the maximum is
  std::vector<double> at_samples;    // degrees C, at thermal_samples(scene)
  std::vector<double> at_points;     // degrees C, at the extra points asked for
  HeatBalance balance;
  std::vector<double> bore_heat;     // W into each bore's coolant (the layout's order)
  CoolantCircuits circuits;          // each circuit's flow, pressure drop and coolant rise
  // s: the cooling time at the hottest sample (the part's centre line reaching the eject
  // temperature there) and, under the coupled condition, the cycle (fill + pack + it + open);
  // ejectable: the hottest sample below the eject temperature (else the part never sets there).
  double cooling_time = 0, cycle_time = 0;
  bool ejectable = true;
  geometry::Vec3 slowest = geometry::Vec3::Zero();  // the place that cools last (the hottest, at one wall)
  double slowest_wall = 0;                          // mm, the part's wall there
  int cycle_iterations = 1;          // solves of the coupled cycle's fixed point
  WallDifference across;             // the core/cavity difference
  std::optional<SideSummaries> sides;  // each side of the part on its own (cavity.parting)
  double seconds = 0;                // the solve (and the model's construction)
  mesh::SurfaceField field;          // filled when a field was asked for
};

// Solves for the layout. `points`: extra points (e.g. a user's CSV); `field_edge` > 0: also the
// field on the cavity surface refined to edges of about that length (mm). Under the coupled
// condition with neither thermal.cycle.cooling nor part_film given, the film follows the cycle
// the solution needs (the cooling time at its hottest sample) until the two agree within 1 %:
// 2-4 solves (the optimiser keeps the nominal cycle's film: a stated linearisation).
CavityTemperature cavity_temperature(const mold::Scene& scene, const mold::Layout& layout, const ThermalQuery& query,
                                     const std::vector<geometry::Vec3>& points = {}, double field_edge = 0);

// Why a point asked for (mtcs thermal --samples) has no steel temperature: outside the block's
// bounds, inside a box cavity (the part), or inside a bore (the coolant, where the line sinks are
// singular); empty when it lies in the steel or on its surface.
std::string not_in_steel(const mold::Scene& scene, const mold::Layout& layout, const geometry::Vec3& p);
// The points of a CSV with columns x,y,z (io::read_points_csv), each in the steel: io::InputError
// naming the file, the point's line and why otherwise.
std::vector<geometry::Vec3> read_steel_points(const std::string& path, const mold::Scene& scene, const mold::Layout& layout);

}  // namespace mtcs::eval
