// MOLD.yaml -> MoldSpec, with one clear error per problem (docs/mold-spec.md lists the fields).

#include "mtcs/mold/mold_spec.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <sstream>

#include <Eigen/Geometry>

#include "mtcs/mesh/mesh_check.h"
#include "mtcs/mesh/mesh_io.h"
#include "scene_check.h"
#include "mtcs/io/number_text.h"
#include "mtcs/io/yaml_reader.h"

namespace mtcs::mold {

using io::YamlReader;
using io::indexed;
using geometry::Vec3;
namespace {

constexpr double kHuge = 1e12;
// thermal.cavity_void: surface without thermal.void_panel: panels this wide (mm).
constexpr double kDefaultVoidPanel = 8;

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

// `scale` as a number or [sx, sy, sz], each > 0 (a negative factor would turn the mesh inside out).
Vec3 parse_scale(const YamlReader& r, const YAML::Node& n, const std::string& path) {
  if (n.IsSequence()) {
    if (n.size() != 3) r.fail(n, path, "expected a factor or three factors [sx, sy, sz]");
    return {r.number(n[0], at(path, 0), 1e-9, 1e9), r.number(n[1], at(path, 1), 1e-9, 1e9),
            r.number(n[2], at(path, 2), 1e-9, 1e9)};
  }
  const double f = r.number(n, path, 1e-9, 1e9);
  return {f, f, f};
}

// `rotate`: {axis: [x, y, z], degrees: a} (right-handed about the axis through the origin), or a
// list of them applied in order.
Eigen::Matrix3d parse_rotate(const YamlReader& r, const YAML::Node& n, const std::string& path) {
  if (n.IsSequence()) {
    Eigen::Matrix3d m = Eigen::Matrix3d::Identity();
    for (std::size_t i = 0; i < n.size(); ++i) m = parse_rotate(r, n[i], at(path, i)) * m;
    return m;
  }
  r.expect_map(n, path, {"axis", "degrees"});
  if (!n["axis"] || !n["degrees"]) r.fail(n, path, "a rotation needs axis: [x, y, z] and degrees");
  const Vec3 axis = r.vec3(n["axis"], path + ".axis");
  if (!(axis.norm() > 0)) r.fail(n["axis"], path + ".axis", "the axis must not be zero");
  const double deg = r.number(n["degrees"], path + ".degrees", -360, 360);
  return Eigen::AngleAxisd(deg * 3.14159265358979323846 / 180, axis.normalized()).toRotationMatrix();
}

// The mesh of a block, cavity or keep-out map `n` ("mesh", and optionally "scale", "rotate",
// "translate"): read, checked (closed, oriented outwards, no self-intersection), then scaled,
// rotated and translated in that order, about the file's origin.
MeshSource parse_mesh(const YamlReader& r, const YAML::Node& n, const std::string& prefix) {
  const YAML::Node& file = n["mesh"];
  const std::string path = prefix + ".mesh";
  MeshSource m;
  const std::string rel = r.text(file, path);
  const std::filesystem::path base = std::filesystem::path(r.file()).parent_path();
  m.path = (base / rel).lexically_normal().string();
  if (n["translate"]) m.translate = r.vec3(n["translate"], prefix + ".translate");
  const Vec3 scale = n["scale"] ? parse_scale(r, n["scale"], prefix + ".scale") : Vec3(1, 1, 1);
  const Eigen::Matrix3d rotate = n["rotate"] ? parse_rotate(r, n["rotate"], prefix + ".rotate") : Eigen::Matrix3d::Identity();
  std::error_code unreadable;  // a name too long, a folder without access: no exception, a clear error
  if (!std::filesystem::exists(m.path, unreadable))
    r.fail(file, path, "mesh file not found: " + m.path + (unreadable ? " (" + unreadable.message() + ")" : ""));
  try {
    m.mesh = mesh::read_mesh(m.path);
  } catch (const mesh::MeshError& e) {
    r.fail(file, path, e.what());
  }
  if (double(m.mesh.triangles.size()) > kMaxSpecTriangles)
    r.fail(file, path, m.path + ": " + std::to_string(m.mesh.triangles.size()) + " triangles, more than " +
                           std::to_string(long(kMaxSpecTriangles)) + ": simplify the mesh (e.g. quadric edge collapse)");
  const std::string problem = mesh::closed_mesh_problem(m.mesh);
  if (!problem.empty()) r.fail(file, path, m.path + ": " + problem);
  if (m.mesh.signed_volume() < 0) r.fail(file, path, m.path + ": the mesh is oriented inwards (negative volume)");
  // As `mtcs interfere` checks its solids: a self-intersecting surface bounds no solid.
  const mesh::MeshCheck check = mesh::check_mesh(m.mesh);
  if (!check.ok()) r.fail(file, path, m.path + ": not the surface of a solid: " + check.message());
  for (Vec3& v : m.mesh.vertices) v = rotate * Vec3(v.cwiseProduct(scale));
  m.mesh.translate(m.translate);
  return m;
}

// translate, scale and rotate place a mesh: refused beside a box, patch or cylinder.
void mesh_only(const YamlReader& r, const YAML::Node& n, const std::string& prefix) {
  if (n["mesh"]) return;
  for (const char* key : {"translate", "scale", "rotate"})
    if (n[key]) r.fail(n[key], prefix + "." + key, std::string(key) + " applies to a mesh only");
}

// The two axes along a face's plane, in x, y, z order.
std::array<int, 2> plane_axes(Face f) {
  const int k = axis_of(f);
  return k == 0 ? std::array{1, 2} : k == 1 ? std::array{0, 2} : std::array{0, 1};
}

std::array<double, 2> parse_vec2(const YamlReader& r, const YAML::Node& n, const std::string& path) {
  if (!n.IsSequence() || n.size() != 2) r.fail(n, path, "expected two numbers [a, b]");
  return {r.number(n[0], at(path, 0), -kHuge, kHuge), r.number(n[1], at(path, 1), -kHuge, kHuge)};
}

// A rectangle on a block face: {face: +z, min: [x, y], max: [x, y]} (the two coordinates along
// the face, in x, y, z order), stored as a flat box on the face's plane.
Box parse_patch(const YamlReader& r, const YAML::Node& n, const Box& block, Face& face) {
  const std::string path = "cavity.patch";
  r.expect_map(n, path, {"face", "min", "max"});
  if (!n["face"] || !n["min"] || !n["max"]) r.fail(n, path, "a patch needs face, min: [a, b] and max: [a, b]");
  face = parse_face(r, n["face"], path + ".face");
  const auto lo = parse_vec2(r, n["min"], path + ".min"), hi = parse_vec2(r, n["max"], path + ".max");
  const auto axes = plane_axes(face);
  const int k = axis_of(face);
  Box b;
  b.min[k] = b.max[k] = face_plane(block, face);
  const char* names = "xyz";
  for (int m = 0; m < 2; ++m) {
    const int a = axes[std::size_t(m)];
    b.min[a] = lo[std::size_t(m)], b.max[a] = hi[std::size_t(m)];
    if (!(b.max[a] > b.min[a])) r.fail(n["max"][m], at(path + ".max", std::size_t(m)), "max must exceed min");
    if (b.min[a] < block.min[a] || b.max[a] > block.max[a])
      r.fail(b.min[a] < block.min[a] ? n["min"][m] : n["max"][m],
             at(path + (b.min[a] < block.min[a] ? ".min" : ".max"), std::size_t(m)),
             std::string("the patch leaves the block's face along ") + names[a]);
  }
  return b;
}

// How many surface samples (sample_box, sample_patch) or sub-triangles (sample_mesh) the cavity
// asks for, in double: a limit before any loop counts them in int.
double surface_sample_estimate(const Cavity& c) {
  const double h = c.sample_spacing;
  const auto cells = [h](double length) { return std::max(1.0, std::ceil(length / h)); };
  if (c.mesh) {
    double pieces = 0;
    const auto& m = c.mesh->mesh;
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      const Vec3 a = m.corner(t, 0), b = m.corner(t, 1), d = m.corner(t, 2);
      const double k = cells(2 * std::max({(b - a).norm(), (d - b).norm(), (a - d).norm()}));
      pieces += k * k;
    }
    return pieces;
  }
  const Vec3 size = c.box->size();
  if (c.is_patch()) {
    int lo = 0;
    size.minCoeff(&lo);
    return cells(size[(lo + 1) % 3]) * cells(size[(lo + 2) % 3]);
  }
  return 2 * (cells(size.x()) * cells(size.y()) + cells(size.y()) * cells(size.z()) + cells(size.z()) * cells(size.x()));
}

Cavity parse_cavity(const YamlReader& r, const YAML::Node& n, const Box& block) {
  r.expect_map(n, "cavity",
               {"mesh", "translate", "scale", "rotate", "box", "patch", "sample_spacing", "wall_thickness", "parting"});
  mesh_only(r, n, "cavity");
  Cavity c;
  if (int(bool(n["mesh"])) + int(bool(n["box"])) + int(bool(n["patch"])) > 1)
    r.fail(n, "cavity", "give one of mesh, box or patch");
  if (n["mesh"]) {
    c.mesh = parse_mesh(r, n, "cavity");
  } else if (n["box"]) {
    c.box = parse_box(r, n["box"], "cavity.box");
  } else if (n["patch"]) {
    Face f = Face::PosZ;
    c.box = parse_patch(r, n["patch"], block, f);
    c.patch_face = f;
  } else {
    r.fail(n, "cavity", "the cavity needs a mesh (file), a box or a patch");
  }
  if (n["sample_spacing"]) c.sample_spacing = r.number(n["sample_spacing"], "cavity.sample_spacing", 1e-3, kHuge);
  if (const YAML::Node w = n["wall_thickness"]; w && w.IsScalar() && w.Scalar() == "local") {
    if (!c.mesh) r.fail(w, "cavity.wall_thickness", "local needs a mesh cavity (a box's or a patch's wall is one number: give it in mm)");
    c.local_thickness = true;
  } else if (w) {
    c.wall_thickness = r.number(w, "cavity.wall_thickness", 1e-6, kHuge);
  }
  if (const YAML::Node p = n["parting"]) {
    if (c.is_patch()) r.fail(p, "cavity.parting", "a patch is one face of the part: it has no two sides to part");
    r.expect_map(p, "cavity.parting", {"core", "at"});
    if (!p["core"]) r.fail(p, "cavity.parting.core", "the block face on the core half's side is needed (e.g. +z)");
    if (!p["at"]) r.fail(p, "cavity.parting.at", "the parting plane's coordinate along that axis is needed (mm)");
    Parting parting;
    parting.core = parse_face(r, p["core"], "cavity.parting.core");
    const int axis = axis_of(parting.core);
    parting.at = r.number(p["at"], "cavity.parting.at", block.min[axis], block.max[axis]);
    c.parting = parting;
  }
  return c;
}

// After the scene check: a part in the wrong units is named as such, not as too many samples.
void check_samples(const YamlReader& r, const YAML::Node& n, const Cavity& c) {
  const double samples = surface_sample_estimate(c);
  if (!(samples <= kMaxSurfaceSamples)) {
    std::ostringstream msg;
    msg << "the cavity's surface at this spacing needs about " << samples << " samples, more than "
        << kMaxSurfaceSamples << "; raise sample_spacing";
    r.fail(n["sample_spacing"] ? n["sample_spacing"] : n, n["sample_spacing"] ? "cavity.sample_spacing" : "cavity", msg.str());
  }
}

KeepOut parse_keep_out(const YamlReader& r, const YAML::Node& n, const std::string& path) {
  r.expect_map(n, path, {"name", "cylinder", "mesh", "translate", "scale", "rotate", "clearance"});
  mesh_only(r, n, path);
  KeepOut k;
  k.name = n["name"] ? r.text(n["name"], path + ".name") : path;
  if (n["cylinder"] && n["mesh"]) r.fail(n, path, "give either cylinder or mesh, not both");
  if (n["cylinder"]) {
    const YAML::Node& c = n["cylinder"];
    r.expect_map(c, path + ".cylinder", {"p0", "p1", "radius"});
    if (!c["p0"] || !c["p1"] || !c["radius"]) r.fail(c, path + ".cylinder", "a cylinder needs p0, p1 and radius");
    k.cylinder = geometry::Cylinder{r.vec3(c["p0"], path + ".cylinder.p0"), r.vec3(c["p1"], path + ".cylinder.p1"),
                                    r.number(c["radius"], path + ".cylinder.radius", 1e-9, kHuge)};
  } else if (n["mesh"]) {
    k.mesh = parse_mesh(r, n, path);
  } else {
    r.fail(n, path, "a keep-out needs a cylinder or a mesh");
  }
  if (n["clearance"]) k.clearance = r.number(n["clearance"], path + ".clearance", 0, kHuge);
  return k;
}

// `baffles: true`: the defaults; false: none.
std::optional<BaffleSpec> parse_baffles(const YamlReader& r, const YAML::Node& n) {
  BaffleSpec b;
  if (n.IsScalar()) return r.boolean(n, "drilling.baffles") ? std::optional(b) : std::nullopt;
  r.expect_map(n, "drilling.baffles", {"faces", "kinds", "max", "tube"});
  if (n["faces"]) b.faces = parse_faces(r, n["faces"], "drilling.baffles.faces");
  if (n["kinds"]) {
    const YAML::Node& k = n["kinds"];
    r.expect_sequence(k, "drilling.baffles.kinds");
    b.kinds.clear();
    for (std::size_t i = 0; i < k.size(); ++i) {
      const std::string name = r.text(k[i], at("drilling.baffles.kinds", i));
      const std::optional<CircuitKind> kind = circuit_kind(name);
      if (!kind || *kind == CircuitKind::Drilled)
        r.fail(k[i], at("drilling.baffles.kinds", i), "unknown kind '" + name + "': expected baffle or bubbler");
      b.kinds.push_back(*kind);
    }
    if (b.kinds.empty()) r.fail(k, "drilling.baffles.kinds", "at least one of baffle, bubbler");
  }
  if (n["max"]) b.max = r.integer(n["max"], "drilling.baffles.max", 0, 1000);
  if (n["tube"]) {
    const YAML::Node& t = n["tube"];
    if (!t.IsSequence() || t.size() != 2)
      r.fail(t, "drilling.baffles.tube", "expected [outside, inside]: the bubbler tube's diameters over the bore's, e.g. [0.7, 0.55]");
    b.tube_outer = r.number(t[0], "drilling.baffles.tube[0]", 0.1, 0.95);
    b.tube_inner = r.number(t[1], "drilling.baffles.tube[1]", 0.05, b.tube_outer - 1e-3);
  }
  return b;
}

Drilling parse_drilling(const YamlReader& r, const YAML::Node& n) {
  r.expect_map(n, "drilling", {"diameters", "axis_parallel", "max_angle_deg", "allowed_faces",
                               "max_depth_ratio", "tip_angle_deg", "min_overlap", "access_map", "baffles"});
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
  if (n["access_map"]) {
    const YAML::Node& m = n["access_map"];
    r.expect_map(m, "drilling.access_map", {"grid", "cells", "entry_step"});
    AccessMapSpec a;
    if (m["grid"]) a.grid = r.integer(m["grid"], "drilling.access_map.grid", 8, 512);
    if (m["cells"]) {
      const YAML::Node& c = m["cells"];
      if (!c.IsSequence() || c.size() != 2) r.fail(c, "drilling.access_map.cells", "expected [rows, cols]");
      a.rows = r.integer(c[0], "drilling.access_map.cells[0]", 2, 1024);
      a.cols = r.integer(c[1], "drilling.access_map.cells[1]", 2, 1024);
    }
    if (m["entry_step"]) a.entry_step = r.number(m["entry_step"], "drilling.access_map.entry_step", 1e-3, kHuge);
    d.access_map = a;
  }
  if (n["baffles"]) d.baffles = parse_baffles(r, n["baffles"]);
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
  r.expect_map(n, "objectives", {"use", "scales", "target_wall_distance", "cost", "production"});
  Objectives o;
  if (n["use"]) {
    r.expect_sequence(n["use"], "objectives.use");
    o.use.clear();
    for (std::size_t i = 0; i < n["use"].size(); ++i) {
      const std::string s = r.text(n["use"][i], at("objectives.use", i));
      const auto objective = objective_named(s);
      if (!objective) r.fail(n["use"][i], at("objectives.use", i), "expected " + kObjectiveNames + "; got '" + s + "'");
      if (std::find(o.use.begin(), o.use.end(), *objective) != o.use.end())
        r.fail(n["use"][i], at("objectives.use", i), "'" + s + "' is listed twice: each objective once");
      o.use.push_back(*objective);
    }
    if (o.use.empty()) r.fail(n["use"], "objectives.use", "at least one objective is needed");
  }
  if (n["scales"]) {
    const YAML::Node& s = n["scales"];
    r.expect_map(s, "objectives.scales", {"uniformity", "worst_covered", "cost", "temperature_mean", "temperature_std",
                                          "temperature_max", "cycle_time", "cost_per_part",
                                          "temperature_difference", "temperature_std_side"});
    auto scale = [&](const char* key, double& into) {
      if (s[key]) into = r.number(s[key], std::string("objectives.scales.") + key, 1e-12, kHuge);
    };
    scale("uniformity", o.scale_uniformity);
    scale("worst_covered", o.scale_worst_covered);
    scale("cost", o.scale_cost);
    scale("temperature_mean", o.scale_temperature_mean);
    scale("temperature_std", o.scale_temperature_std);
    scale("temperature_max", o.scale_temperature_max);
    scale("cycle_time", o.scale_cycle_time);
    scale("cost_per_part", o.scale_cost_per_part);
    scale("temperature_difference", o.scale_temperature_difference);
    scale("temperature_std_side", o.scale_temperature_std_side);
  }
  if (n["target_wall_distance"])
    o.target_wall_distance = parse_length(r, n["target_wall_distance"], "objectives.target_wall_distance");
  if (n["cost"]) {
    const YAML::Node& c = n["cost"];
    r.expect_map(c, "objectives.cost", {"setup", "per_mm", "deep_factor", "plug", "insert"});
    if (c["setup"]) o.cost_setup = r.number(c["setup"], "objectives.cost.setup", 0, kHuge);
    if (c["per_mm"]) o.cost_per_mm = r.number(c["per_mm"], "objectives.cost.per_mm", 0, kHuge);
    if (c["deep_factor"]) o.cost_deep_factor = r.number(c["deep_factor"], "objectives.cost.deep_factor", 0, kHuge);
    if (c["plug"]) o.cost_plug = r.number(c["plug"], "objectives.cost.plug", 0, kHuge);
    if (c["insert"]) o.cost_insert = r.number(c["insert"], "objectives.cost.insert", 0, kHuge);
  }
  if (n["production"]) {
    const YAML::Node& p = n["production"];
    r.expect_map(p, "objectives.production", {"parts", "machine_rate"});
    Objectives::Production production;
    if (!p["parts"]) r.fail(p, "objectives.production.parts", "the lot size is needed (parts the mold makes)");
    if (!p["machine_rate"]) r.fail(p, "objectives.production.machine_rate", "the machine's cost per hour is needed");
    production.parts = r.number(p["parts"], "objectives.production.parts", 1, kHuge);
    production.machine_rate = r.number(p["machine_rate"], "objectives.production.machine_rate", 0, kHuge);
    o.production = production;
  }
  for (std::size_t i = 0; i < o.use.size(); ++i)
    if (o.use[i] == Objective::CostPerPart && !o.production)
      r.fail(n["use"][i], at("objectives.use", i),
             "cost_per_part needs objectives.production: {parts: N, machine_rate: cost per hour}");
  return o;
}

// thermal.cavity_condition and what it reads: part_film, part_temperature, cycle. Either key of
// the part's condition asks for the coupled condition; heat_flux belongs to the flux model.
void parse_cavity_condition(const YamlReader& r, const YAML::Node& n, ThermalSpec& t) {
  constexpr double kPerM2 = 1e-6;  // W/(m^2 K) -> W/(mm^2 K)
  if (n["part_film"]) t.part_film = kPerM2 * r.number(n["part_film"], "thermal.part_film", 1e-6, 1e9);
  if (n["part_temperature"])
    t.part_temperature = r.number(n["part_temperature"], "thermal.part_temperature", -273.15, 5000);
  if (t.part_film || t.part_temperature) t.cavity_condition = CavityCondition::Coupled;
  if (n["cavity_condition"]) {
    const std::string s = r.text(n["cavity_condition"], "thermal.cavity_condition");
    if (s == "coupled") t.cavity_condition = CavityCondition::Coupled;
    else if (s == "flux") t.cavity_condition = CavityCondition::Flux;
    else r.fail(n["cavity_condition"], "thermal.cavity_condition", "expected coupled or flux; got '" + s + "'");
  }
  const bool coupled = t.cavity_condition == CavityCondition::Coupled;
  if (!coupled && (n["part_film"] || n["part_temperature"]))
    r.fail(n["part_film"] ? n["part_film"] : n["part_temperature"], n["part_film"] ? "thermal.part_film" : "thermal.part_temperature",
           "belongs to cavity_condition: coupled, not flux");
  if (coupled && n["heat_flux"])
    r.fail(n["heat_flux"], "thermal.heat_flux",
           "is the flux model's (cavity_condition: flux); the coupled condition takes part_film and part_temperature");
  if (n["cycle"]) {
    const YAML::Node& c = n["cycle"];
    r.expect_map(c, "thermal.cycle", {"fill", "pack", "open", "cooling"});
    MoldingCycle& m = t.cycle;
    if (c["fill"]) m.fill = r.number(c["fill"], "thermal.cycle.fill", 0, 1e5);
    if (c["pack"]) m.pack = r.number(c["pack"], "thermal.cycle.pack", 0, 1e5);
    if (c["open"]) m.open = r.number(c["open"], "thermal.cycle.open", 0, 1e5);
    if (c["cooling"]) m.cooling = r.number(c["cooling"], "thermal.cycle.cooling", 1e-3, 1e5);
  }
  if (t.part_temperature && coupled && *t.part_temperature <= t.coolant_temperature)
    r.fail(n["part_temperature"], "thermal.part_temperature", "the part must be hotter than the coolant");
}

// thermal.coolant.pump: [[l/min, bar], ...], the flow rising and the pressure falling (bar -> Pa);
// it drives the circuits alone (no flow rate, supply pressure or film beside it).
std::vector<std::pair<double, double>> parse_pump(const YamlReader& r, const YAML::Node& c) {
  const YAML::Node& n = c["pump"];
  const std::string field = "thermal.coolant.pump";
  for (const char* other : {"flow_rate", "supply_pressure", "film"})
    if (c[other]) r.fail(c, "thermal.coolant", std::string("give pump or ") + other + ", not both (the pump sets each circuit's flow)");
  r.expect_sequence(n, field);
  if (n.size() < 2) r.fail(n, field, "at least two points [l/min, bar] of the pump's curve");
  std::vector<std::pair<double, double>> pump;
  for (std::size_t i = 0; i < n.size(); ++i) {
    const std::string where = at(field, i);
    if (!n[i].IsSequence() || n[i].size() != 2) r.fail(n[i], where, "a point [l/min, bar]");
    const double flow = r.number(n[i][0], where + "[0]", 0, 1e6), bar = r.number(n[i][1], where + "[1]", 0, 1e4);
    if (!pump.empty() && (flow <= pump.back().first || bar * 1e5 > pump.back().second))
      r.fail(n[i], where, "the curve's flow must rise and its pressure not rise from point to point");
    pump.emplace_back(flow, bar * 1e5);
  }
  if (!(pump.front().second > 0)) r.fail(n[0], at(field, 0), "the pump gives no pressure at its first point");
  return pump;
}

// thermal: SI in the file, the thermal module's units (mm, W, degrees C) in the spec.
ThermalSpec parse_thermal(const YamlReader& r, const YAML::Node& n) {
  r.expect_map(n, "thermal", {"steel_conductivity", "coolant", "ambient", "adiabatic_faces", "heat_flux", "regions",
                              "polymer", "tier", "elements_per_bore", "wall_images", "cell_size",
                              "objective_surface", "cavity_void", "void_panel", "sample_spacing",
                              "cavity_condition", "part_film", "part_temperature", "cycle"});
  constexpr double kPerM = 1e-3, kPerM2 = 1e-6;  // W/(m K) -> W/(mm K); W/m^2 -> W/mm^2
  constexpr double kCold = -273.15, kHot = 5000;  // degrees C
  ThermalSpec t;
  if (n["steel_conductivity"])
    t.conductivity = kPerM * r.number(n["steel_conductivity"], "thermal.steel_conductivity", 1e-6, 1e6);
  if (n["coolant"]) {
    const YAML::Node& c = n["coolant"];
    r.expect_map(c, "thermal.coolant",
                 {"temperature", "film", "flow_rate", "supply_pressure", "pump", "roughness", "min_reynolds", "max_rise",
                  "balance", "rise"});
    if (c["film"] && c["flow_rate"]) r.fail(c, "thermal.coolant", "give film or flow_rate, not both");
    if (c["film"] && c["supply_pressure"])
      r.fail(c, "thermal.coolant", "give film or supply_pressure, not both (the pressure sets each circuit's flow and film)");
    if (c["temperature"]) t.coolant_temperature = r.number(c["temperature"], "thermal.coolant.temperature", kCold, kHot);
    if (c["film"]) t.coolant_film = kPerM2 * r.number(c["film"], "thermal.coolant.film", 1e-9, 1e12);
    if (c["flow_rate"]) t.flow_rate = r.number(c["flow_rate"], "thermal.coolant.flow_rate", 1e-6, 1e6);
    constexpr double kPaPerBar = 1e5;
    if (c["supply_pressure"])
      t.supply_pressure = kPaPerBar * r.number(c["supply_pressure"], "thermal.coolant.supply_pressure", 1e-6, 1e4);
    if (c["pump"]) t.pump = parse_pump(r, c);
    // The water properties behind Gnielinski are tabulated from 0 to 106 degrees C.
    if (t.flowing() && (t.coolant_temperature < 0.01 || t.coolant_temperature > 106))
      r.fail(c["temperature"] ? c["temperature"] : c, "thermal.coolant.temperature",
             "with a flow rate, a supply pressure or a pump the coolant is water: 0 to 106 degrees C");
    if (c["roughness"]) t.roughness = r.number(c["roughness"], "thermal.coolant.roughness", 0, 10);
    if (c["min_reynolds"]) t.min_reynolds = r.number(c["min_reynolds"], "thermal.coolant.min_reynolds", 0, 1e8);
    if (c["max_rise"]) t.max_rise = r.number(c["max_rise"], "thermal.coolant.max_rise", 1e-6, 1e4);
    if (c["balance"]) t.balance = r.number(c["balance"], "thermal.coolant.balance", 1e-6, 0.99);  // the band 1 +- b
    if (c["rise"]) t.coolant_rise = r.boolean(c["rise"], "thermal.coolant.rise");
  }
  if (n["ambient"]) {
    const YAML::Node& a = n["ambient"];
    r.expect_map(a, "thermal.ambient", {"temperature", "film"});
    if (a["temperature"]) t.ambient_temperature = r.number(a["temperature"], "thermal.ambient.temperature", kCold, kHot);
    if (a["film"]) t.ambient_film = kPerM2 * r.number(a["film"], "thermal.ambient.film", 0, 1e12);
  }
  if (n["adiabatic_faces"]) {
    r.expect_sequence(n["adiabatic_faces"], "thermal.adiabatic_faces");
    for (std::size_t i = 0; i < n["adiabatic_faces"].size(); ++i)
      t.adiabatic_faces.push_back(parse_face(r, n["adiabatic_faces"][i], at("thermal.adiabatic_faces", i)));
  }
  if (n["heat_flux"]) t.heat_flux = kPerM2 * r.number(n["heat_flux"], "thermal.heat_flux", 0, 1e12);
  if (n["regions"]) {
    r.expect_sequence(n["regions"], "thermal.regions");
    for (std::size_t i = 0; i < n["regions"].size(); ++i) {
      const YAML::Node& g = n["regions"][i];
      const std::string path = at("thermal.regions", i);
      r.expect_map(g, path, {"box", "heat_flux"});
      if (!g["box"] || !g["heat_flux"]) r.fail(g, path, "a region needs box and heat_flux");
      t.regions.push_back({parse_box(r, g["box"], path + ".box"), kPerM2 * r.number(g["heat_flux"], path + ".heat_flux", 0, 1e12)});
    }
  }
  if (n["polymer"]) {
    const YAML::Node& p = n["polymer"];
    r.expect_map(p, "thermal.polymer", {"melt_temperature", "eject_temperature", "diffusivity", "density", "specific_heat"});
    Polymer& m = t.polymer;
    if (p["melt_temperature"]) m.melt_temperature = r.number(p["melt_temperature"], "thermal.polymer.melt_temperature", kCold, kHot);
    if (p["eject_temperature"]) m.eject_temperature = r.number(p["eject_temperature"], "thermal.polymer.eject_temperature", kCold, kHot);
    if (p["diffusivity"]) m.diffusivity = r.number(p["diffusivity"], "thermal.polymer.diffusivity", 1e-9, 1e6);
    if (p["density"]) m.density = r.number(p["density"], "thermal.polymer.density", 1e-6, 1e6);
    if (p["specific_heat"]) m.specific_heat = r.number(p["specific_heat"], "thermal.polymer.specific_heat", 1e-6, 1e7);
    if (!(m.eject_temperature < m.melt_temperature))
      r.fail(p["eject_temperature"] ? p["eject_temperature"] : p, "thermal.polymer.eject_temperature",
             "the eject temperature must be below the melt temperature");
  }
  parse_cavity_condition(r, n, t);
  // The cycle-time proxy cools the part towards the coolant: it must be colder than ejection.
  if (!(t.coolant_temperature < t.polymer.eject_temperature)) {
    const YAML::Node& c = n["coolant"] && n["coolant"]["temperature"] ? n["coolant"]["temperature"] : n;
    r.fail(c, "thermal.coolant.temperature", "the coolant must be colder than the polymer's eject temperature");
  }
  if (n["tier"]) {
    const std::string s = r.text(n["tier"], "thermal.tier");
    if (s == "t1") t.tier = ThermalTier::T1;
    else if (s == "t2") t.tier = ThermalTier::T2;
    else if (s == "t2d") t.tier = ThermalTier::T2d;
    else if (s == "fd") t.tier = ThermalTier::Fd;
    else if (s == "t0")
      r.fail(n["tier"], "thermal.tier",
             "tier 0 is not a temperature model: choose the objectives uniformity and worst_covered instead");
    else r.fail(n["tier"], "thermal.tier", "expected t1, t2, t2d or fd; got '" + s + "'");
  }
  if (n["elements_per_bore"]) t.elements_per_bore = r.integer(n["elements_per_bore"], "thermal.elements_per_bore", 1, 1000);
  if (n["wall_images"]) t.wall_images = r.integer(n["wall_images"], "thermal.wall_images", 1, 3);
  if (n["cell_size"]) t.cell_size = r.number(n["cell_size"], "thermal.cell_size", 1e-3, kHuge);
  if (n["sample_spacing"]) t.sample_spacing = r.number(n["sample_spacing"], "thermal.sample_spacing", 1e-3, kHuge);
  if (n["objective_surface"]) {
    const std::string s = r.text(n["objective_surface"], "thermal.objective_surface");
    if (s == "heated") t.objective_surface = ObjectiveSurface::Heated;
    else if (s == "all") t.objective_surface = ObjectiveSurface::All;
    else r.fail(n["objective_surface"], "thermal.objective_surface", "expected heated or all; got '" + s + "'");
  }
  if (n["cavity_void"]) {
    const std::string s = r.text(n["cavity_void"], "thermal.cavity_void");
    if (s == "plane") t.void_plane = true;
    else if (s == "surface") t.void_panel = kDefaultVoidPanel;
    else if (s != "ignore")
      r.fail(n["cavity_void"], "thermal.cavity_void", "expected ignore, plane or surface; got '" + s + "'");
  }
  if (n["void_panel"]) {
    if (t.void_panel == 0) r.fail(n["void_panel"], "thermal.void_panel", "needs cavity_void: surface");
    t.void_panel = r.number(n["void_panel"], "thermal.void_panel", 0.1, kHuge);
  }
  return t;
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

int default_min_circuits(const Box& part) {
  const double longest = part.size().maxCoeff();
  return std::clamp(int(std::ceil(longest / kPartLengthPerCircuit - 1e-9)), 1, 3);
}

MoldSpec load_mold_spec(const std::string& path) {
  const YamlReader r(path);
  const YAML::Node root = r.load();
  r.expect_map(root, "", {"units", "block", "cavity", "keep_outs", "drilling", "clearances", "circuits",
                          "objectives", "thermal", "penalty"});
  MoldSpec s;
  s.path = path;
  if (root["units"]) {
    s.units = r.text(root["units"], "units");
    if (s.units != "mm") r.fail(root["units"], "units", "only mm is supported");
  }
  if (!root["block"]) r.fail(root, "block", "the block is required");
  {
    const YAML::Node& b = root["block"];
    r.expect_map(b, "block", {"box", "mesh", "translate", "scale", "rotate"});
    mesh_only(r, b, "block");
    if (b["box"] && b["mesh"]) r.fail(b, "block", "give either box or mesh, not both");
    if (b["box"]) s.block.box = parse_box(r, b["box"], "block.box");
    else if (b["mesh"]) s.block.mesh = parse_mesh(r, b, "block");
    else r.fail(b, "block", "the block needs a box or a mesh");
  }
  if (root["cavity"])
    s.cavity = parse_cavity(r, root["cavity"], s.block.box ? *s.block.box : s.block.mesh->mesh.bounds());
  if (root["keep_outs"]) {
    r.expect_sequence(root["keep_outs"], "keep_outs");
    for (std::size_t i = 0; i < root["keep_outs"].size(); ++i)
      s.keep_outs.push_back(parse_keep_out(r, root["keep_outs"][i], at("keep_outs", i)));
  }
  if (root["drilling"]) s.drilling = parse_drilling(r, root["drilling"]);
  if (s.drilling.access_map && !(s.cavity && s.cavity->mesh))
    r.fail(root["drilling"]["access_map"], "drilling.access_map", "accessibility maps need a cavity mesh");
  if (root["clearances"]) s.clearances = parse_clearances(r, root["clearances"]);
  if (root["circuits"]) s.circuits = parse_circuits(r, root["circuits"]);
  if (!(root["circuits"] && root["circuits"]["min"]) && s.cavity)
    s.circuits.min = std::min(s.circuits.max, default_min_circuits(s.cavity->bounds()));
  if (root["objectives"]) s.objectives = parse_objectives(r, root["objectives"]);
  // Temperatures and wall distances are taken on the part's surface; a block alone has only a cost.
  const bool use_given = root["objectives"] && root["objectives"]["use"];
  if (!s.cavity && !use_given) s.objectives.use = {Objective::Cost};
  if (!s.cavity)
    for (std::size_t i = 0; i < s.objectives.use.size(); ++i)
      if (s.objectives.use[i] != Objective::Cost)
        r.fail(root["objectives"]["use"][i], at("objectives.use", i),
               "'" + to_string(s.objectives.use[i]) + "' is taken on the part's surface: give a cavity, or use only cost");
  for (std::size_t i = 0; i < s.objectives.use.size(); ++i)
    if (s.objectives.use[i] == Objective::TemperatureStdSide && s.cavity && !s.cavity->parting)
      r.fail(root["objectives"]["use"][i], at("objectives.use", i),
             s.cavity->is_patch() ? "temperature_std_side needs a part with two sides: a patch is one face"
                                  : "temperature_std_side needs the mold's two sides: cavity.parting: {core: +z, at: MM}");
  if (root["thermal"]) s.thermal = parse_thermal(r, root["thermal"]);
  // A mesh cavity (a part) is a void the line sinks must see: without it they rank its layouts
  // no better than the wall distances do (experiments/thermal/void_surface.md).
  // Under the coupled condition a box cavity's wall takes the part's film through the void's
  // panels too (the plane cut moves a fixed flux only).
  const bool coupled = s.thermal.cavity_condition == CavityCondition::Coupled;
  const bool box_void = s.cavity && s.cavity->box && !s.cavity->is_patch();
  if (!(root["thermal"] && root["thermal"]["cavity_void"]) && s.cavity && (s.cavity->mesh || (coupled && box_void)))
    s.thermal.void_panel = kDefaultVoidPanel;
  if (coupled && s.cavity && !s.cavity->is_patch() && s.thermal.void_panel == 0 && root["thermal"]["cavity_void"])
    r.fail(root["thermal"]["cavity_void"], "thermal.cavity_void",
           "the coupled cavity condition needs the void as a surface for the line sinks: cavity_void: surface");
  // Coarser samples only: the cavity's count check then bounds the thermal set too.
  if (s.thermal.sample_spacing && s.cavity && *s.thermal.sample_spacing < s.cavity->sample_spacing)
    r.fail(root["thermal"]["sample_spacing"], "thermal.sample_spacing",
           "must be at least the cavity's sample_spacing (" + io::shortest(s.cavity->sample_spacing) + " mm)");
  if (root["penalty"]) s.penalty = parse_penalty(r, root["penalty"]);
  check_scene(r, root, s);
  if (s.cavity) check_samples(r, root["cavity"], *s.cavity);
  return s;
}

std::string to_string(CircuitKind k) {
  switch (k) {
    case CircuitKind::Drilled: return "drilled";
    case CircuitKind::Baffle: return "baffle";
    case CircuitKind::Bubbler: return "bubbler";
  }
  return "drilled";
}

std::optional<CircuitKind> circuit_kind(const std::string& name) {
  for (const CircuitKind k : {CircuitKind::Drilled, CircuitKind::Baffle, CircuitKind::Bubbler})
    if (to_string(k) == name) return k;
  return std::nullopt;
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

int axis_of(Face f) { return int(f) / 2; }  // Face lists +x, -x, +y, -y, +z, -z

double face_plane(const Box& block, Face f) {
  const int k = axis_of(f);
  return normal_of(f)[k] > 0 ? block.max[k] : block.min[k];
}

Face nearest_face(const Box& block, const Vec3& p, const std::vector<Face>& faces) {
  const auto off = [&](Face f) { return std::abs(p[axis_of(f)] - face_plane(block, f)); };
  Face best = faces.front();
  for (const Face f : faces)
    if (off(f) < off(best)) best = f;
  return best;
}

double Drilling::point_length(double diameter) const {
  return 0.5 * diameter / std::tan(tip_angle_deg * 3.14159265358979323846 / 360);
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
    case Objective::TemperatureMean: return "temperature_mean";
    case Objective::TemperatureStd: return "temperature_std";
    case Objective::TemperatureMax: return "temperature_max";
    case Objective::CycleTime: return "cycle_time";
    case Objective::CostPerPart: return "cost_per_part";
    case Objective::TemperatureDifference: return "temperature_difference";
    case Objective::TemperatureStdSide: return "temperature_std_side";
  }
  return "?";
}

std::optional<Objective> objective_named(const std::string& name) {
  for (const auto o : {Objective::Uniformity, Objective::WorstCovered, Objective::Cost, Objective::TemperatureMean,
                       Objective::TemperatureStd, Objective::TemperatureMax, Objective::CycleTime,
                       Objective::CostPerPart, Objective::TemperatureDifference, Objective::TemperatureStdSide})
    if (to_string(o) == name) return o;
  return std::nullopt;
}

bool is_temperature_objective(Objective o) {
  return o == Objective::TemperatureMean || o == Objective::TemperatureStd || o == Objective::TemperatureMax ||
         o == Objective::CycleTime || o == Objective::CostPerPart || o == Objective::TemperatureDifference ||
         o == Objective::TemperatureStdSide;
}

std::string to_string(ObjectiveSurface s) { return s == ObjectiveSurface::Heated ? "heated" : "all"; }

std::optional<ThermalTier> thermal_tier(const std::string& name) {
  for (const ThermalTier t : {ThermalTier::T1, ThermalTier::T2, ThermalTier::T2d, ThermalTier::Fd})
    if (to_string(t) == name) return t;
  return std::nullopt;
}

std::string to_string(CavityCondition c) { return c == CavityCondition::Coupled ? "coupled" : "flux"; }

std::string to_string(ThermalTier t) {
  switch (t) {
    case ThermalTier::T1: return "t1";
    case ThermalTier::T2: return "t2";
    case ThermalTier::T2d: return "t2d";
    case ThermalTier::Fd: return "fd";
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
