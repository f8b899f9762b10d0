#pragma once
// The mold spec: what a designer writes in MOLD.yaml (docs/mold-spec.md documents every field,
// with units and defaults). Plain data; meshes are loaded and validated by load_mold_spec.

#include <optional>
#include <string>
#include <vector>

#include "mtcs/geometry/primitives.h"
#include "mtcs/geometry/triangle_distance.h"
#include "mtcs/mesh/triangle_mesh.h"

namespace mtcs::mold {

using geometry::Box;
using geometry::Vec3;

// A face of the block, by its outward normal: +x, -x, +y, -y, +z, -z.
enum class Face { PosX, NegX, PosY, NegY, PosZ, NegZ };
std::string to_string(Face f);
Vec3 normal_of(Face f);
Face face_of_normal(const Vec3& n);  // the axis direction closest to n

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

struct Cavity {
  std::optional<Box> box;           // a primitive part: no mesh code runs for it
  std::optional<MeshSource> mesh;
  double sample_spacing = 3.0;      // mm between cavity-surface samples
  double wall_thickness = 2.5;      // mm
};

struct KeepOut {
  std::string name;
  std::optional<geometry::Cylinder> cylinder;
  std::optional<MeshSource> mesh;
  double clearance = 3.0;  // mm between a bore and this keep-out
};

struct Drilling {
  std::vector<double> diameters{8.0};
  bool axis_parallel = true;
  double max_angle_deg = 0;          // drill axis against the entry face's normal
  std::vector<Face> allowed_faces{Face::PosX, Face::NegX, Face::PosY, Face::NegY};
  double max_depth_ratio = 50;       // drilled length / diameter
  double tip_angle_deg = 118;        // drill point angle: overshoot 0.5 D cot(tip/2)
  double min_overlap = 0;            // extra length beyond a junction, mm
};

struct Clearances {
  double bore_bore = 4;
  Length bore_cavity{1.0, true};
  double bore_surface = 3;
};

struct CircuitLimits {
  int min = 1, max = 4;
  int min_waypoints = 2, max_waypoints = 12;
  std::vector<Face> inlet_faces{Face::NegY}, outlet_faces{Face::NegY};
};

enum class Objective { Uniformity, WorstCovered, Cost };
std::string to_string(Objective o);

struct Objectives {
  std::vector<Objective> use{Objective::Uniformity, Objective::WorstCovered, Objective::Cost};
  double scale_uniformity = 1, scale_worst_covered = 1, scale_cost = 1;
  Length target_wall_distance{2.0, true};
  double cost_setup = 20, cost_per_mm = 0.05, cost_deep_factor = 0.02, cost_plug = 5;

  // The divisor that makes objective o comparable to the others.
  double scale(Objective o) const {
    return o == Objective::Uniformity ? scale_uniformity : o == Objective::WorstCovered ? scale_worst_covered : scale_cost;
  }
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
  Penalty penalty;
};

// Reads, validates and loads a mold spec with its meshes. Every problem throws io::InputError
// with the file, line and column, and the field's path (e.g. "keep_outs[2].clearance").
MoldSpec load_mold_spec(const std::string& path);

}  // namespace mtcs::mold
