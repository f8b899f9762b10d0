#pragma once
// The mold spec: what a designer writes in MOLD.yaml (docs/mold-spec.md documents every field,
// with units and defaults). Plain data; meshes are loaded and validated by load_mold_spec.

#include <optional>
#include <string>
#include <vector>

#include "mtcs/geometry/primitives.h"
#include "mtcs/geometry/triangle_distance.h"
#include "mtcs/mesh/triangle_mesh.h"
#include "mtcs/mold/genome.h"

namespace mtcs::mold {

using geometry::Box;
using geometry::Vec3;

// A face of the block, by its outward normal: +x, -x, +y, -y, +z, -z.
enum class Face { PosX, NegX, PosY, NegY, PosZ, NegZ };
std::string to_string(Face f);
Vec3 normal_of(Face f);
Face face_of_normal(const Vec3& n);  // the axis direction closest to n
int axis_of(Face f);                 // 0, 1, 2 for x, y, z
double face_plane(const Box& block, Face f);  // the face's coordinate along its axis
// Of `faces`, the one whose plane lies nearest p (the first on a tie).
Face nearest_face(const Box& block, const Vec3& p, const std::vector<Face>& faces);

// A length that is either absolute (mm) or a multiple of the bore diameter ("2.0D").
struct Length {
  double value = 0;
  bool per_diameter = false;
  double at(double diameter) const { return per_diameter ? value * diameter : value; }
};

struct MeshSource {
  std::string path;  // resolved against the spec's folder
  Vec3 translate = Vec3::Zero();
  mesh::TriangleMesh mesh;  // loaded, translated and validated
};

struct Block {
  std::optional<Box> box;
  std::optional<MeshSource> mesh;
};

// The cavity is one of: a box (a primitive part, a void in the block: no mesh code runs for it),
// a closed mesh (a void), or a patch: a rectangle on a block face where the melt touches the
// steel from outside (the reference block of shared/cases/thermal), no void. A patch is stored
// as a flat box (zero extent along the face's normal) in `box`, with `patch_face` set, so code
// that only needs the cavity's bounds reads `box` alike.
// The most cavity-surface samples (sub-triangles for a mesh) a spec may ask for: beyond it the
// reader says to raise sample_spacing instead of exhausting memory or overflowing counts.
inline constexpr double kMaxSurfaceSamples = 2e7;

// Where the mold opens (cavity.parting): the parting plane, `at` mm along the axis of `core`,
// and the block face on the core half's side. Straight pull: the part's two sides, for the
// spread per side (eval/part_sides.h).
struct Parting {
  Face core = Face::PosZ;
  double at = 0;  // mm
};

struct Cavity {
  std::optional<Box> box;
  std::optional<MeshSource> mesh;
  std::optional<Face> patch_face;   // set: `box` is a flat rectangle on this block face
  double sample_spacing = 3.0;      // mm between cavity-surface samples
  double wall_thickness = 2.5;      // mm; with local_thickness, the thickest wall (the Scene sets it)
  bool local_thickness = false;     // `wall_thickness: local`: per place, from the mesh (mesh/wall_thickness.h)
  std::optional<Parting> parting;

  bool is_patch() const { return patch_face.has_value(); }
  Box bounds() const { return box ? *box : mesh->mesh.bounds(); }
};

struct KeepOut {
  std::string name;
  std::optional<geometry::Cylinder> cylinder;
  std::optional<MeshSource> mesh;
  double clearance = 3.0;  // mm between a bore and this keep-out
};

// Angled drilling guided by accessibility maps (docs/mold-spec.md, `drilling.access_map`): the
// cavity mesh voxelised on `grid`^3 voxels, maps of rows x cols directions, entry points rounded
// to multiples of `entry_step` (and drilled lengths up to one) so that bores share their maps.
struct AccessMapSpec {
  int grid = 64;
  int rows = 32, cols = 32;
  double entry_step = 1.0;  // mm
};

// Blind bores with a baffle blade or a bubbler tube (drilling.baffles, docs/coolant-circuits.md):
// the faces they are drilled from (along the face's normal), the kinds the optimiser may lay, how
// many per layout (besides circuits.max), and the bubbler's tube as fractions of the bore's
// diameter (outside and inside).
struct BaffleSpec {
  std::vector<Face> faces{Face::PosZ};
  std::vector<CircuitKind> kinds{CircuitKind::Baffle, CircuitKind::Bubbler};
  int max = 2;
  double tube_outer = 0.7, tube_inner = 0.55;
};

struct Drilling {
  std::vector<double> diameters{8.0};
  bool axis_parallel = true;
  double max_angle_deg = 0;          // drill axis against the entry face's normal
  std::vector<Face> allowed_faces{Face::PosX, Face::NegX, Face::PosY, Face::NegY};
  double max_depth_ratio = 50;       // drilled length / diameter
  double tip_angle_deg = 118;        // drill point angle: overshoot 0.5 D cot(tip/2)
  double min_overlap = 0;            // extra length beyond a junction, mm
  std::optional<AccessMapSpec> access_map;  // set: the `drillable` constraint and AM-guided mutation
  std::optional<BaffleSpec> baffles;        // set: layouts may hold baffles and bubblers

  // The drill point's length past a hole's end, 0.5 D cot(tip/2), mm.
  double point_length(double diameter) const;
  // The faces a baffle or bubbler is drilled from (drilling.baffles.faces, or the allowed faces).
  const std::vector<Face>& blind_faces() const { return baffles ? baffles->faces : allowed_faces; }
};

struct Clearances {
  double bore_bore = 4;
  Length bore_cavity{1.0, true};
  double bore_surface = 3;
};

struct CircuitLimits {
  int min = 1, max = 4;  // without circuits.min in the spec: default_min_circuits of the part
  int min_waypoints = 2, max_waypoints = 12;
  std::vector<Face> inlet_faces{Face::NegY}, outlet_faces{Face::NegY};
};

// Tier 0 (wall distances): Uniformity, WorstCovered. Physics (the thermal section's tier):
// the area-weighted mean, standard deviation and maximum of the cavity-surface temperature,
// and the cycle-time proxy at the hottest sample.
enum class Objective {
  Uniformity,
  WorstCovered,
  Cost,
  TemperatureMean,
  TemperatureStd,
  TemperatureMax,
  CycleTime,
  CostPerPart,           // the drilling cost over the lot plus the machine's time per part
  TemperatureDifference, // the core/cavity difference across the part's wall (warpage)
  TemperatureStdSide     // the in-plane spread of the core or cavity side, the larger (cavity.parting)
};
std::string to_string(Objective o);
// The objective of that name (as to_string spells it), or none.
std::optional<Objective> objective_named(const std::string& name);
inline const std::string kObjectiveNames =
    "uniformity, worst_covered, cost, temperature_mean, temperature_std, temperature_max, cycle_time, cost_per_part, "
    "temperature_difference or temperature_std_side";
// Needs a thermal solve (not the tier-0 wall distances).
bool is_temperature_objective(Objective o);

// Without objectives.use a spec gets temperatures (the thermal section's tier): their spread,
// their peak and the drilling cost. The scales are the bundled molds': a kelvin of spread weighs
// as much as 10 K of peak or 1 000 of cost.
struct Objectives {
  std::vector<Objective> use{Objective::TemperatureStd, Objective::TemperatureMax, Objective::Cost};
  double scale_uniformity = 5, scale_worst_covered = 20, scale_cost = 1000;                   // mm, mm, cost
  double scale_temperature_mean = 10, scale_temperature_std = 1, scale_temperature_max = 10;  // K
  double scale_cycle_time = 1;  // s: 1 s of cycle as 1 K of spread (evening the spread by a hotter mold costs cycle)
  double scale_cost_per_part = 0.1;          // the cost units per part
  double scale_temperature_difference = 1;   // K
  double scale_temperature_std_side = 1;     // K
  Length target_wall_distance{2.0, true};
  double cost_setup = 20, cost_per_mm = 0.05, cost_deep_factor = 0.02, cost_plug = 5;
  double cost_insert = 10;  // a baffle's blade or a bubbler's tube, with its fitting
  // objectives.production, which cost_per_part needs: the lot the mold makes and what an hour
  // of the molding machine costs (the drilling cost's units).
  struct Production {
    double parts = 0;
    double machine_rate = 0;  // per hour
  };
  std::optional<Production> production;

  // The divisor that makes objective o comparable to the others.
  double scale(Objective o) const {
    switch (o) {
      case Objective::Uniformity: return scale_uniformity;
      case Objective::WorstCovered: return scale_worst_covered;
      case Objective::Cost: return scale_cost;
      case Objective::TemperatureMean: return scale_temperature_mean;
      case Objective::TemperatureStd: return scale_temperature_std;
      case Objective::TemperatureMax: return scale_temperature_max;
      case Objective::CycleTime: return scale_cycle_time;
      case Objective::CostPerPart: return scale_cost_per_part;
      case Objective::TemperatureDifference: return scale_temperature_difference;
      case Objective::TemperatureStdSide: return scale_temperature_std_side;
    }
    return 1;
  }
};

// The physics of the thermal objectives (docs/mold-spec.md, "thermal"). The spec is written in
// SI units (W/(m K), W/(m^2 K), W/m^2); stored here in the thermal module's units: mm, W,
// degrees C (conductivity W/(mm K), films W/(mm^2 K), fluxes W/mm^2).
enum class ThermalTier { T1, T2, T2d, Fd };
std::string to_string(ThermalTier t);
// The tier of that name (as to_string spells it), or none.
std::optional<ThermalTier> thermal_tier(const std::string& name);

// Which cavity samples the temperature objectives (and every summary of them: `mtcs thermal`,
// finite-volume re-scores) cover: Heated, those where heat enters (flux > 0: the faces this mold
// half cools; a face whose part gives its heat to the other half is left out); All, every one.
enum class ObjectiveSurface { Heated, All };
std::string to_string(ObjectiveSurface s);

// Cavity surface inside `box` takes `flux` instead of the default (later regions win).
struct HeatRegion {
  Box box;
  double flux = 0;  // W/mm^2
};

// The molded polymer, for the cycle-time proxy and the default heat flux (ABS-like defaults).
struct Polymer {
  double melt_temperature = 230;    // degrees C
  double eject_temperature = 90;    // degrees C, at the part's centre line
  double diffusivity = 0.095;       // mm^2/s (0.2 W/(m K) / (1050 kg/m^3 * 2000 J/(kg K)))
  double density = 1050;            // kg/m^3
  double specific_heat = 2000;      // J/(kg K)
};

// How the part heats the steel through the cavity (docs/mold-spec.md, thermal.cavity_condition):
// Coupled, the part's cycle-averaged response to the wall, q = h_p (T_p - T_wall), so that no
// steel runs hotter than T_p (eval/part_coupling.h); Flux, the older model: a fixed flux
// (thermal.heat_flux or eval::default_heat_flux), whatever the wall's temperature.
enum class CavityCondition { Flux, Coupled };
std::string to_string(CavityCondition c);

// The molding cycle (s): fill, pack and cooling in the mold, then open (the part ejected, the
// cavity takes no heat). cooling: none, the cooling time with the wall at the coolant's
// temperature (eval::nominal_cycle).
struct MoldingCycle {
  double fill = 1, pack = 3, open = 5;
  std::optional<double> cooling;
};

struct ThermalSpec {
  double conductivity = 0.03;              // W/(mm K) (30 W/(m K): tool steel)
  double coolant_temperature = 40;         // degrees C
  // The bore wall: neither -> Dirichlet at the coolant temperature; a film; or a flow rate per
  // circuit from which eval::coolant_film finds the film (Gnielinski).
  std::optional<double> coolant_film;      // W/(mm^2 K)
  std::optional<double> flow_rate;         // l/min per circuit
  // The circuits' hydraulics (eval/circuit_hydraulics.h). supply_pressure: across each circuit's
  // ports; with flow_rate a limit the circuit's drop must keep under, alone what drives each
  // circuit's own flow (and film). The bores' equivalent roughness; the shop's limits.
  std::optional<double> supply_pressure;   // Pa
  // Or a pump's curve: (total flow l/min, pressure Pa) points, the flow rising, the pressure
  // falling; the circuits take it in parallel, each the flow the common pressure drives.
  std::vector<std::pair<double, double>> pump;
  double roughness = 0.045;                // mm (Moody's commercial steel)
  double min_reynolds = 1e4;               // turbulent above (Moldflow's band)
  double max_rise = 3;                     // K, coolant outlet over inlet
  std::optional<double> balance;           // each circuit's heat within this fraction of the mean
  // Water flows through the circuits: each bore's flow, and the circuits' checks, are known.
  bool flowing() const { return flow_rate || supply_pressure || !pump.empty(); }
  // The coolant warms along each circuit in the model (with a flow), or stays at the inlet's.
  bool coolant_rise = true;
  double ambient_temperature = 25;         // degrees C
  double ambient_film = 1e-5;              // W/(mm^2 K) (10 W/(m^2 K): free convection)
  std::vector<Face> adiabatic_faces;       // e.g. the parting plane
  std::optional<double> heat_flux;         // W/mm^2 into the steel; none: eval::default_heat_flux
  std::vector<HeatRegion> regions;
  Polymer polymer;
  CavityCondition cavity_condition = CavityCondition::Flux;
  std::optional<double> part_film;         // W/(mm^2 K): h_p for the whole cavity (coupled)
  std::optional<double> part_temperature;  // degrees C: T_p (coupled; default the melt's)
  MoldingCycle cycle;
  ThermalTier tier = ThermalTier::T2d;
  int elements_per_bore = 4;               // M of T2/T2d
  // Reflection levels of the block's faces summed exactly at the bores' walls by T1/T2/T2d (the
  // samples take one; farther levels join the block's charge and dipole): 2 keeps the reference
  // block at 0.14 K RMS, 1 costs 0.56x per solve (experiments/thermal/plate_wall_images.md).
  int wall_images = 2;
  double cell_size = 2;                    // mm, T3 (fd)
  // mm between the samples of the temperature objectives (eval::thermal_samples); none: the
  // cavity's sample_spacing. Coarser than the cavity's: the line sinks' work per new channel
  // is proportional to the samples (experiments/thermal/plate_samples.md).
  std::optional<double> sample_spacing;
  ObjectiveSurface objective_surface = ObjectiveSurface::Heated;
  // thermal.cavity_void: plane: the line-sink tiers cut the block at a box cavity's most heated
  // face (mtcs/thermal/void_plane.h); surface (a mesh cavity's default): the cavity's wall as
  // panels void_panel mm wide (thermal.void_panel; src/thermal/cavity/void_surface.h); ignore (a box
  // cavity's default): they see no void.
  bool void_plane = false;
  double void_panel = 0;  // mm; 0: no void surface
};

enum class PenaltyVariant { ConstrainedDomination, StaticLinear, StaticQuadratic, Death };
std::string to_string(PenaltyVariant v);
// The variant of that name (as to_string spells it), or none.
std::optional<PenaltyVariant> penalty_variant(const std::string& name);
inline const std::string kPenaltyVariantNames = "constrained_domination, static_linear, static_quadratic or death";

struct Penalty {
  PenaltyVariant variant = PenaltyVariant::ConstrainedDomination;
  double power = 2;
  double weight = 1;
};

struct MoldSpec {
  std::string path;  // the YAML file
  std::string units = "mm";
  Block block;
  std::optional<Cavity> cavity;
  std::vector<KeepOut> keep_outs;
  Drilling drilling;
  Clearances clearances;
  CircuitLimits circuits;
  Objectives objectives;
  ThermalSpec thermal;
  Penalty penalty;
};

// circuits.min when the spec does not give it: one circuit per 40 mm of the part's longest side,
// 1 to 3 (experiments/defaults/README.md: on a 105 mm part the default ES stopped at 1-2 circuits
// on 10 of 11 seeds with min 1, leaving a lobe of the part 50 mm and more from any bore).
inline constexpr double kPartLengthPerCircuit = 40;  // mm
int default_min_circuits(const Box& part);

// Reads, validates and loads a mold spec with its meshes. Every problem throws io::InputError
// with the file, line and column, and the field's path (e.g. "keep_outs[2].clearance").
MoldSpec load_mold_spec(const std::string& path);

}  // namespace mtcs::mold
