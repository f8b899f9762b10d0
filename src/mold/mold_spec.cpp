// MOLD.yaml -> MoldSpec, with one clear error per problem (docs/mold-spec.md lists the fields).

#include "mtcs/mold/mold_spec.h"

#include <charconv>
#include <cmath>
#include <filesystem>

#include "mtcs/mesh/mesh_io.h"
#include "mtcs/io/yaml_reader.h"

namespace mtcs::mold {

using io::YamlReader;
using io::indexed;
namespace {

constexpr double kHuge = 1e12;

std::string at(const std::string& path, std::size_t i) { return indexed(path, i); }

Face parse_face(const YamlReader& r, const YAML::Node& n, const std::string& path) {
  const std::string s = r.text(n, path);
  if (s == "+x") return Face::PosX;
  if (s == "-x") return Face::NegX;
  if (s == "+y") return Face::PosY;
  if (s == "-y") return Face::NegY;
  if (s == "+z") return Face::PosZ;
  if (s == "-z") return Face::NegZ;
  r.fail(n, path, "expected a block face: +x, -x, +y, -y, +z or -z; got '" + s + "'");
}

std::vector<Face> parse_faces(const YamlReader& r, const YAML::Node& n, const std::string& path) {
  r.expect_sequence(n, path);
  if (n.size() == 0) r.fail(n, path, "at least one face is needed");
  std::vector<Face> faces;
  for (std::size_t i = 0; i < n.size(); ++i) faces.push_back(parse_face(r, n[i], at(path, i)));
  return faces;
}

// A length in mm, or a multiple of the bore diameter written "2.0D".
Length parse_length(const YamlReader& r, const YAML::Node& n, const std::string& path) {
  if (n.IsScalar() && !n.Scalar().empty() && n.Scalar().back() == 'D') {
    const std::string& s = n.Scalar();
    double v = 0;
    const auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size() - 1, v);
    if (s.size() < 2 || ec != std::errc() || ptr != s.data() + s.size() - 1 || !std::isfinite(v) || v < 0)
      r.fail(n, path, "expected a length in mm or a multiple of the diameter such as 2.0D; got '" + s + "'");
    return {v, true};
  }
  return {r.number(n, path, 0, kHuge), false};
}

Box parse_box(const YamlReader& r, const YAML::Node& n, const std::string& path) {
  r.expect_map(n, path, {"min", "max"});
  if (!n["min"] || !n["max"]) r.fail(n, path, "a box needs min: [x, y, z] and max: [x, y, z]");
  Box b{r.vec3(n["min"], path + ".min"), r.vec3(n["max"], path + ".max")};
  if (!((b.max - b.min).array() > 0).all()) r.fail(n["max"], path + ".max", "max must exceed min in x, y and z");
  return b;
}

MeshSource parse_mesh(const YamlReader& r, const YAML::Node& file, const YAML::Node& translate,
                      const std::string& path, const std::string& translate_path) {
  MeshSource m;
  const std::string rel = r.text(file, path);
  const std::filesystem::path base = std::filesystem::path(r.file()).parent_path();
  m.path = (base / rel).lexically_normal().string();
  if (translate) m.translate = r.vec3(translate, translate_path);
  if (!std::filesystem::exists(m.path)) r.fail(file, path, "mesh file not found: " + m.path);
  try {
    m.mesh = mesh::read_mesh(m.path);
  } catch (const mesh::MeshError& e) {
    r.fail(file, path, e.what());
  }
  const std::string problem = mesh::closed_mesh_problem(m.mesh);
  if (!problem.empty()) r.fail(file, path, m.path + ": " + problem);
  if (m.mesh.signed_volume() < 0) r.fail(file, path, m.path + ": the mesh is oriented inwards (negative volume)");
  m.mesh.translate(m.translate);
  return m;
}

Cavity parse_cavity(const YamlReader& r, const YAML::Node& n) {
  r.expect_map(n, "cavity", {"mesh", "translate", "box", "sample_spacing", "wall_thickness"});
  Cavity c;
  if (n["mesh"] && n["box"]) r.fail(n, "cavity", "give either mesh or box, not both");
  if (n["mesh"]) c.mesh = parse_mesh(r, n["mesh"], n["translate"], "cavity.mesh", "cavity.translate");
  else if (n["box"]) c.box = parse_box(r, n["box"], "cavity.box");
  else r.fail(n, "cavity", "the cavity needs a mesh (file) or a box");
  if (n["translate"] && !n["mesh"]) r.fail(n["translate"], "cavity.translate", "translate applies to a mesh only");
  if (n["sample_spacing"]) c.sample_spacing = r.number(n["sample_spacing"], "cavity.sample_spacing", 1e-3, kHuge);
  if (n["wall_thickness"]) c.wall_thickness = r.number(n["wall_thickness"], "cavity.wall_thickness", 1e-6, kHuge);
  return c;
}

KeepOut parse_keep_out(const YamlReader& r, const YAML::Node& n, const std::string& path) {
  r.expect_map(n, path, {"name", "cylinder", "mesh", "translate", "clearance"});
  KeepOut k;
  k.name = n["name"] ? r.text(n["name"], path + ".name") : path;
  if (n["cylinder"] && n["mesh"]) r.fail(n, path, "give either cylinder or mesh, not both");
  if (n["cylinder"]) {
    const YAML::Node& c = n["cylinder"];
    r.expect_map(c, path + ".cylinder", {"p0", "p1", "radius"});
    if (!c["p0"] || !c["p1"] || !c["radius"]) r.fail(c, path + ".cylinder", "a cylinder needs p0, p1 and radius");
    k.cylinder = geometry::Cylinder{r.vec3(c["p0"], path + ".cylinder.p0"), r.vec3(c["p1"], path + ".cylinder.p1"),
                                    r.number(c["radius"], path + ".cylinder.radius", 1e-9, kHuge)};
    if (n["translate"]) r.fail(n["translate"], path + ".translate", "translate applies to a mesh only");
  } else if (n["mesh"]) {
    k.mesh = parse_mesh(r, n["mesh"], n["translate"], path + ".mesh", path + ".translate");
  } else {
    r.fail(n, path, "a keep-out needs a cylinder or a mesh");
  }
  if (n["clearance"]) k.clearance = r.number(n["clearance"], path + ".clearance", 0, kHuge);
  return k;
}

Drilling parse_drilling(const YamlReader& r, const YAML::Node& n) {
  r.expect_map(n, "drilling", {"diameters", "axis_parallel", "max_angle_deg", "allowed_faces",
                               "max_depth_ratio", "tip_angle_deg", "min_overlap"});
  Drilling d;
  if (n["diameters"]) {
    r.expect_sequence(n["diameters"], "drilling.diameters");
    d.diameters.clear();
    for (std::size_t i = 0; i < n["diameters"].size(); ++i)
      d.diameters.push_back(r.number(n["diameters"][i], at("drilling.diameters", i), 1e-6, kHuge));
    if (d.diameters.empty()) r.fail(n["diameters"], "drilling.diameters", "at least one diameter is needed");
  }
  if (n["axis_parallel"]) d.axis_parallel = r.boolean(n["axis_parallel"], "drilling.axis_parallel");
  if (n["max_angle_deg"]) d.max_angle_deg = r.number(n["max_angle_deg"], "drilling.max_angle_deg", 0, 89);
  if (n["allowed_faces"]) d.allowed_faces = parse_faces(r, n["allowed_faces"], "drilling.allowed_faces");
  if (n["max_depth_ratio"]) d.max_depth_ratio = r.number(n["max_depth_ratio"], "drilling.max_depth_ratio", 1, 1e4);
  if (n["tip_angle_deg"]) d.tip_angle_deg = r.number(n["tip_angle_deg"], "drilling.tip_angle_deg", 60, 180);
  if (n["min_overlap"]) d.min_overlap = r.number(n["min_overlap"], "drilling.min_overlap", 0, kHuge);
  return d;
}

Clearances parse_clearances(const YamlReader& r, const YAML::Node& n) {
  r.expect_map(n, "clearances", {"bore_bore", "bore_cavity", "bore_surface"});
  Clearances c;
  if (n["bore_bore"]) c.bore_bore = r.number(n["bore_bore"], "clearances.bore_bore", 0, kHuge);
  if (n["bore_cavity"]) c.bore_cavity = parse_length(r, n["bore_cavity"], "clearances.bore_cavity");
  if (n["bore_surface"]) c.bore_surface = r.number(n["bore_surface"], "clearances.bore_surface", 0, kHuge);
  return c;
}

CircuitLimits parse_circuits(const YamlReader& r, const YAML::Node& n) {
  r.expect_map(n, "circuits", {"min", "max", "waypoints", "inlet_faces", "outlet_faces"});
  CircuitLimits c;
  if (n["min"]) c.min = r.integer(n["min"], "circuits.min", 1, 1000);
  if (n["max"]) c.max = r.integer(n["max"], "circuits.max", 1, 1000);
  if (c.max < c.min) r.fail(n["max"] ? n["max"] : n, "circuits.max", "max is below min");
  if (n["waypoints"]) {
    const YAML::Node& w = n["waypoints"];
    if (!w.IsSequence() || w.size() != 2) r.fail(w, "circuits.waypoints", "expected [min, max] waypoints per circuit");
    c.min_waypoints = r.integer(w[0], "circuits.waypoints[0]", 2, 10000);
    c.max_waypoints = r.integer(w[1], "circuits.waypoints[1]", c.min_waypoints, 10000);
  }
  if (n["inlet_faces"]) c.inlet_faces = parse_faces(r, n["inlet_faces"], "circuits.inlet_faces");
  if (n["outlet_faces"]) c.outlet_faces = parse_faces(r, n["outlet_faces"], "circuits.outlet_faces");
  return c;
}

Objectives parse_objectives(const YamlReader& r, const YAML::Node& n) {
  r.expect_map(n, "objectives", {"use", "scales", "target_wall_distance", "cost"});
  Objectives o;
  if (n["use"]) {
    r.expect_sequence(n["use"], "objectives.use");
    o.use.clear();
    for (std::size_t i = 0; i < n["use"].size(); ++i) {
      const std::string s = r.text(n["use"][i], at("objectives.use", i));
      if (s == "uniformity") o.use.push_back(Objective::Uniformity);
      else if (s == "worst_covered") o.use.push_back(Objective::WorstCovered);
      else if (s == "cost") o.use.push_back(Objective::Cost);
      else r.fail(n["use"][i], at("objectives.use", i), "expected uniformity, worst_covered or cost; got '" + s + "'");
    }
    if (o.use.empty()) r.fail(n["use"], "objectives.use", "at least one objective is needed");
  }
  if (n["scales"]) {
    const YAML::Node& s = n["scales"];
    r.expect_map(s, "objectives.scales", {"uniformity", "worst_covered", "cost"});
    if (s["uniformity"]) o.scale_uniformity = r.number(s["uniformity"], "objectives.scales.uniformity", 1e-12, kHuge);
    if (s["worst_covered"]) o.scale_worst_covered = r.number(s["worst_covered"], "objectives.scales.worst_covered", 1e-12, kHuge);
    if (s["cost"]) o.scale_cost = r.number(s["cost"], "objectives.scales.cost", 1e-12, kHuge);
  }
  if (n["target_wall_distance"])
    o.target_wall_distance = parse_length(r, n["target_wall_distance"], "objectives.target_wall_distance");
  if (n["cost"]) {
    const YAML::Node& c = n["cost"];
    r.expect_map(c, "objectives.cost", {"setup", "per_mm", "deep_factor", "plug"});
    if (c["setup"]) o.cost_setup = r.number(c["setup"], "objectives.cost.setup", 0, kHuge);
    if (c["per_mm"]) o.cost_per_mm = r.number(c["per_mm"], "objectives.cost.per_mm", 0, kHuge);
    if (c["deep_factor"]) o.cost_deep_factor = r.number(c["deep_factor"], "objectives.cost.deep_factor", 0, kHuge);
    if (c["plug"]) o.cost_plug = r.number(c["plug"], "objectives.cost.plug", 0, kHuge);
  }
  return o;
}

Penalty parse_penalty(const YamlReader& r, const YAML::Node& n) {
  r.expect_map(n, "penalty", {"variant", "power", "weight"});
  Penalty p;
  if (n["variant"]) {
    const std::string s = r.text(n["variant"], "penalty.variant");
    const auto variant = penalty_variant(s);
    if (!variant) r.fail(n["variant"], "penalty.variant", "expected " + kPenaltyVariantNames + "; got '" + s + "'");
    p.variant = *variant;
  }
  if (n["power"]) p.power = r.number(n["power"], "penalty.power", 1, 4);
  if (n["weight"]) p.weight = r.number(n["weight"], "penalty.weight", 0, kHuge);
  return p;
}

}  // namespace

MoldSpec load_mold_spec(const std::string& path) {
  const YamlReader r(path);
  const YAML::Node root = r.load();
  r.expect_map(root, "", {"units", "block", "cavity", "keep_outs", "drilling", "clearances", "circuits",
                          "objectives", "penalty"});
  MoldSpec s;
  s.path = path;
  if (root["units"]) {
    s.units = r.text(root["units"], "units");
    if (s.units != "mm") r.fail(root["units"], "units", "only mm is supported");
  }
  if (!root["block"]) r.fail(root, "block", "the block is required");
  {
    const YAML::Node& b = root["block"];
    r.expect_map(b, "block", {"box", "mesh", "translate"});
    if (b["box"] && b["mesh"]) r.fail(b, "block", "give either box or mesh, not both");
    if (b["box"]) s.block.box = parse_box(r, b["box"], "block.box");
    else if (b["mesh"]) s.block.mesh = parse_mesh(r, b["mesh"], b["translate"], "block.mesh", "block.translate");
    else r.fail(b, "block", "the block needs a box or a mesh");
  }
  if (root["cavity"]) s.cavity = parse_cavity(r, root["cavity"]);
  if (root["keep_outs"]) {
    r.expect_sequence(root["keep_outs"], "keep_outs");
    for (std::size_t i = 0; i < root["keep_outs"].size(); ++i)
      s.keep_outs.push_back(parse_keep_out(r, root["keep_outs"][i], at("keep_outs", i)));
  }
  if (root["drilling"]) s.drilling = parse_drilling(r, root["drilling"]);
  if (root["clearances"]) s.clearances = parse_clearances(r, root["clearances"]);
  if (root["circuits"]) s.circuits = parse_circuits(r, root["circuits"]);
  if (root["objectives"]) s.objectives = parse_objectives(r, root["objectives"]);
  if (root["penalty"]) s.penalty = parse_penalty(r, root["penalty"]);
  return s;
}

std::string to_string(Face f) {
  static const char* names[] = {"+x", "-x", "+y", "-y", "+z", "-z"};
  return names[int(f)];
}

Vec3 normal_of(Face f) {
  switch (f) {
    case Face::PosX: return Vec3::UnitX();
    case Face::NegX: return -Vec3::UnitX();
    case Face::PosY: return Vec3::UnitY();
    case Face::NegY: return -Vec3::UnitY();
    case Face::PosZ: return Vec3::UnitZ();
    case Face::NegZ: return -Vec3::UnitZ();
  }
  return Vec3::UnitZ();
}

Face face_of_normal(const Vec3& n) {
  int k = 0;
  n.cwiseAbs().maxCoeff(&k);
  const bool pos = n[k] >= 0;
  return k == 0 ? (pos ? Face::PosX : Face::NegX) : k == 1 ? (pos ? Face::PosY : Face::NegY) : (pos ? Face::PosZ : Face::NegZ);
}

std::string to_string(Objective o) {
  switch (o) {
    case Objective::Uniformity: return "uniformity";
    case Objective::WorstCovered: return "worst_covered";
    case Objective::Cost: return "cost";
  }
  return "?";
}

std::optional<PenaltyVariant> penalty_variant(const std::string& name) {
  for (const auto v : {PenaltyVariant::ConstrainedDomination, PenaltyVariant::StaticLinear,
                       PenaltyVariant::StaticQuadratic, PenaltyVariant::Death})
    if (to_string(v) == name) return v;
  return std::nullopt;
}

std::string to_string(PenaltyVariant v) {
  switch (v) {
    case PenaltyVariant::ConstrainedDomination: return "constrained_domination";
    case PenaltyVariant::StaticLinear: return "static_linear";
    case PenaltyVariant::StaticQuadratic: return "static_quadratic";
    case PenaltyVariant::Death: return "death";
  }
  return "?";
}

}  // namespace mtcs::mold
