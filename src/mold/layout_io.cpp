#include "mtcs/mold/layout_io.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>

#include "mtcs/io/atomic_file.h"
#include "mtcs/io/number_text.h"
#include "mtcs/mesh/mesh_io.h"
#include "mtcs/io/yaml_reader.h"

namespace mtcs::mold {

using io::YamlReader;
using io::indexed;

using geometry::Vec3;

namespace {

std::string mm(double v) { return io::shortest(std::round(v * 1e6) / 1e6) + " mm"; }

std::string point(const Vec3& p) { return "[" + io::shortest(p.x()) + ", " + io::shortest(p.y()) + ", " + io::shortest(p.z()) + "]"; }

std::string faces_text(const std::vector<Face>& faces) {
  std::string s;
  for (const Face f : faces) s += (s.empty() ? "" : ", ") + to_string(f);
  return s;
}

// The waypoints of one circuit as written, checked against the drilling rules; what is snapped
// or routed is recorded in `changes`, what cannot be drilled as written is refused at its node.
void check_circuit(const YamlReader& r, const YAML::Node& w, const std::string& path, const MoldSpec& spec, int c,
                   Circuit& circuit, std::vector<LayoutChange>& changes) {
  const Drilling& drill = spec.drilling;
  if (!drill.axis_parallel) return;
  static const char* kAxis = "xyz";
  std::array<bool, 3> drillable{false, false, false};
  for (const Face f : drill.allowed_faces) drillable[std::size_t(axis_of(f))] = true;
  std::vector<Vec3>& pts = circuit.waypoints;
  const Vec3 inlet = pts.front();
  for (std::size_t i = 1; i < pts.size(); ++i) {
    Vec3& p = pts[i];
    const std::string wp = indexed(path, i);
    const std::string who = "circuit " + std::to_string(c) + ", waypoint " + std::to_string(i);
    for (int k = 0; k < 3; ++k) {
      if (drillable[std::size_t(k)] || p[k] == inlet[k]) continue;
      const double off = std::abs(p[k] - inlet[k]);
      const std::string axis(1, kAxis[k]);
      if (off > kLayoutSnap)
        r.fail(w[i], wp,
               who + " leaves the drilling plane of its inlet (" + axis + " = " + mm(inlet[k]) + ", here " + axis +
                   " = " + mm(p[k]) + "): holes must run parallel to an allowed face, and no face in "
                   "drilling.allowed_faces (" + faces_text(drill.allowed_faces) + ") is drilled along " + axis +
                   "; give it " + axis + " = " + io::shortest(inlet[k]) + " or allow a face on " + axis);
      changes.push_back({c, int(i), who + ": " + axis + " snapped from " + io::shortest(p[k]) + " to the inlet's " +
                                        io::shortest(inlet[k]) + " mm (within " + mm(kLayoutSnap) + ")"});
      p[k] = inlet[k];
    }
    // A step along more than one axis is drilled as legs along the axes, longest first.
    const Vec3 d = p - pts[i - 1];
    int moving = 0;
    for (int k = 0; k < 3; ++k) moving += d[k] != 0 ? 1 : 0;
    if (moving > 1) {
      std::string axes;
      for (int k = 0; k < 3; ++k)
        if (d[k] != 0) axes += (axes.empty() ? "" : " and ") + std::string(1, kAxis[k]);
      changes.push_back({c, int(i), who + ": the step from " + point(pts[i - 1]) + " to " + point(p) + " runs along " +
                                        axes + "; drilled as " + std::to_string(moving) +
                                        " axis-parallel holes, longest first (drilling.axis_parallel)"});
    }
  }
}

// Every waypoint of a drilled circuit in the block (its faces included, within kLayoutSnap): a
// point outside would be exported as a hole in the air and scored by models that assume steel.
void check_inside(const YamlReader& r, const YAML::Node& w, const std::string& path, const Box& block, int c,
                  const Circuit& circuit) {
  static const char* kAxis = "xyz";
  for (std::size_t i = 0; i < circuit.waypoints.size(); ++i) {
    const Vec3& p = circuit.waypoints[i];
    for (int k = 0; k < 3; ++k) {
      const bool below = p[k] < block.min[k] - kLayoutSnap, above = p[k] > block.max[k] + kLayoutSnap;
      if (!below && !above) continue;
      const std::string axis(1, kAxis[k]);
      r.fail(w[i], indexed(path, i),
             "circuit " + std::to_string(c) + ", waypoint " + std::to_string(i) + " " + point(p) + " is outside the block: " +
                 axis + " = " + mm(p[k]) + " beyond its " + (below ? "-" : "+") + axis + " face at " +
                 mm(below ? block.min[k] : block.max[k]) + " (the block spans " + point(block.min) + " to " +
                 point(block.max) + " mm)");
    }
  }
}

// A baffle's or bubbler's two waypoints: the entry on a face of drilling.baffles.faces, the tip
// straight below it (within kLayoutSnap), deep enough and inside the block.
void check_blind(const YamlReader& r, const YAML::Node& node, const std::string& path, const MoldSpec& spec,
                 const Box& block, int c, Circuit& circuit) {
  const std::string who = "circuit " + std::to_string(c) + " (" + to_string(circuit.kind) + ")";
  if (!spec.drilling.baffles)
    r.fail(node["kind"], path + ".kind", who + ": the mold spec allows no baffles or bubblers; add drilling.baffles: {faces: [...]}");
  const YAML::Node& w = node["waypoints"];
  if (circuit.waypoints.size() != 2)
    r.fail(w, path + ".waypoints", who + " is one blind hole: give two waypoints, the entry on a face and the tip");
  const BaffleSpec& baffles = *spec.drilling.baffles;
  if (std::find(baffles.kinds.begin(), baffles.kinds.end(), circuit.kind) == baffles.kinds.end())
    r.fail(node["kind"], path + ".kind", who + ": drilling.baffles.kinds of the mold spec does not list " + to_string(circuit.kind));
  const std::vector<Face>& faces = baffles.faces;
  const Vec3 entry = circuit.waypoints[0], tip = circuit.waypoints[1];
  const Face face = nearest_face(block, entry, faces);  // the decoder's (mold::blind_axis)
  if (std::abs(entry[axis_of(face)] - face_plane(block, face)) > kLayoutSnap)
    r.fail(w[0], indexed(path + ".waypoints", 0),
           who + ": the entry " + point(entry) + " is on none of drilling.baffles.faces (" + faces_text(faces) + ")");
  const int k = axis_of(face);
  for (int j = 0; j < 3; ++j)
    if (j != k && std::abs(tip[j] - entry[j]) > kLayoutSnap)
      r.fail(w[1], indexed(path + ".waypoints", 1),
             who + ": the tip " + point(tip) + " is not straight below the entry " + point(entry) +
                 ": a blind hole is drilled along the face's normal");
  const double depth = (tip - entry).dot(-normal_of(face));
  if (depth < circuit.diameter - kLayoutSnap)
    r.fail(w[1], indexed(path + ".waypoints", 1), who + ": the tip is " + mm(depth) + " into the block; at least a diameter (" +
                                                      mm(circuit.diameter) + ") is drilled");
  if (!block.contains(tip))
    r.fail(w[1], indexed(path + ".waypoints", 1), who + ": the tip " + point(tip) + " is outside the block");
  // The drill's point past the tip stays in the block (the decoder would shorten the hole).
  const double point_length = spec.drilling.point_length(circuit.diameter);
  const double room = block.size()[k] - depth;
  if (room <= point_length)
    r.fail(w[1], indexed(path + ".waypoints", 1),
           who + ": the drill's point (" + mm(point_length) + " past the tip) would leave the block's far face, " + mm(room) +
               " beyond the tip");
}

}  // namespace

WrittenLayout read_layout(const std::string& path, const MoldSpec& spec) {
  const Box block = spec.block.box ? *spec.block.box : spec.block.mesh->mesh.bounds();
  const YamlReader r(path);
  const YAML::Node root = r.load();
  r.expect_map(root, "", {"circuits"});
  if (!root["circuits"]) r.fail(root, "circuits", "a layout needs a list of circuits");
  const YAML::Node& cs = root["circuits"];
  r.expect_sequence(cs, "circuits");
  if (cs.size() == 0) r.fail(cs, "circuits", "the layout has no circuit: an empty layout cools nothing, so it is not scored");
  WrittenLayout out;
  Genome& g = out.genome;
  for (std::size_t c = 0; c < cs.size(); ++c) {
    const std::string cp = indexed("circuits", c);
    r.expect_map(cs[c], cp, {"diameter", "waypoints", "kind"});
    if (!cs[c]["diameter"] || !cs[c]["waypoints"]) r.fail(cs[c], cp, "a circuit needs diameter and waypoints");
    Circuit circuit;
    circuit.diameter = r.number(cs[c]["diameter"], cp + ".diameter", 1e-9, 1e9);
    bool listed = false;
    for (const double d : spec.drilling.diameters) listed = listed || std::abs(d - circuit.diameter) <= 1e-9 * d;
    if (!listed) {
      std::ostringstream sizes;
      for (std::size_t k = 0; k < spec.drilling.diameters.size(); ++k) sizes << (k ? ", " : "") << spec.drilling.diameters[k];
      r.fail(cs[c]["diameter"], cp + ".diameter", "not one of drilling.diameters of the mold spec (" + sizes.str() + " mm)");
    }
    const YAML::Node& w = cs[c]["waypoints"];
    r.expect_sequence(w, cp + ".waypoints");
    if (w.size() < 2) r.fail(w, cp + ".waypoints", "a circuit needs at least an inlet and an outlet");
    for (std::size_t i = 0; i < w.size(); ++i)
      circuit.waypoints.push_back(r.vec3(w[i], indexed(cp + ".waypoints", i)));
    bool moves = false;
    for (const Vec3& p : circuit.waypoints) moves = moves || p != circuit.waypoints.front();
    if (!moves) r.fail(w, cp + ".waypoints", "circuit " + std::to_string(c) + " drills nothing: all its waypoints are the same point");
    if (cs[c]["kind"]) {
      const std::string name = r.text(cs[c]["kind"], cp + ".kind");
      const std::optional<CircuitKind> kind = circuit_kind(name);
      if (!kind) r.fail(cs[c]["kind"], cp + ".kind", "unknown kind '" + name + "': expected drilled, baffle or bubbler");
      circuit.kind = *kind;
    }
    if (!is_blind(circuit.kind)) check_inside(r, w, cp + ".waypoints", block, int(c), circuit);
    if (is_blind(circuit.kind)) check_blind(r, cs[c], cp, spec, block, int(c), circuit);
    else check_circuit(r, w, cp + ".waypoints", spec, int(c), circuit, out.changes);
    g.circuits.push_back(std::move(circuit));
  }
  return out;
}

Genome load_layout(const std::string& path, const MoldSpec& spec) { return read_layout(path, spec).genome; }

void save_layout(const std::string& path, const Genome& genome) {
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << YAML::BeginMap << YAML::Key << "circuits" << YAML::Value << YAML::BeginSeq;
  for (const Circuit& c : genome.circuits) {
    out << YAML::BeginMap << YAML::Key << "diameter" << YAML::Value << io::shortest(c.diameter);
    if (is_blind(c.kind)) out << YAML::Key << "kind" << YAML::Value << to_string(c.kind);
    out << YAML::Key << "waypoints" << YAML::Value << YAML::BeginSeq;
    // The fewest digits that read back exactly: a rounded layout reads 35.12, not 35.119999999999997.
    for (const Vec3& p : c.waypoints)
      out << YAML::Flow << YAML::BeginSeq << io::shortest(p.x()) << io::shortest(p.y()) << io::shortest(p.z())
          << YAML::EndSeq;
    out << YAML::EndSeq << YAML::EndMap;
  }
  out << YAML::EndSeq << YAML::EndMap;
  io::AtomicFile file(path);
  file.stream() << "# mtcs layout: circuits of waypoints (inlet first, outlet last), mm\n" << out.c_str() << "\n";
  file.commit();
}

void save_bores_csv(const std::string& path, const Layout& layout) {
  io::AtomicFile file(path);
  auto& out = file.stream();
  const auto n = [](double v) { return io::shortest(v); };
  out << "name,circuit,segment,p0x,p0y,p0z,p1x,p1y,p1z,diameter,entry_face,plugged,dead_end,insert\n";
  for (const Bore& b : layout.bores) {
    out << b.name() << ',' << b.circuit << ',' << b.segment << ',' << n(b.hole.p0.x()) << ',' << n(b.hole.p0.y()) << ','
        << n(b.hole.p0.z()) << ',' << n(b.hole.p1.x()) << ',' << n(b.hole.p1.y()) << ',' << n(b.hole.p1.z()) << ','
        << n(b.diameter) << ',' << to_string(b.entry_face) << ',' << (b.plugged ? 1 : 0) << ',' << n(b.dead_end) << ','
        << (is_blind(b.kind) ? to_string(b.kind) : "") << '\n';
  }
  file.commit();
}

void save_holes_csv(const std::string& path, const Layout& layout) {
  io::AtomicFile file(path);
  auto& out = file.stream();
  const auto n = [](double v) { return io::shortest(v); };
  out << "hole,circuit,entry_x,entry_y,entry_z,direction_x,direction_y,direction_z,diameter,depth,entry_face,"
         "plug_x,plug_y,plug_z,insert\n";
  for (const Bore& b : layout.bores) {
    const Vec3 axis = b.hole.p1 - b.hole.p0;
    const double depth = axis.norm();
    const Vec3 u = depth > 0 ? Vec3(axis / depth) : Vec3::Zero();
    // Directions along an axis print as 1, 0, -1; others to a millionth.
    const auto dir = [&](double v) { return n(std::round(v * 1e6) / 1e6); };
    out << b.name() << ',' << b.circuit << ',' << n(b.hole.p0.x()) << ',' << n(b.hole.p0.y()) << ',' << n(b.hole.p0.z())
        << ',' << dir(u.x()) << ',' << dir(u.y()) << ',' << dir(u.z()) << ',' << n(b.diameter) << ',' << n(depth) << ','
        << to_string(b.entry_face);
    if (b.plugged) out << ',' << n(b.hole.p0.x()) << ',' << n(b.hole.p0.y()) << ',' << n(b.hole.p0.z());
    else out << ",,,";
    out << ',' << (is_blind(b.kind) ? to_string(b.kind) : "") << '\n';
  }
  file.commit();
}

void save_bores_stl(const std::string& path, const Layout& layout) {
  constexpr int kSides = 24;
  mesh::TriangleMesh m;
  for (const Bore& b : layout.bores) {
    const Vec3 axis = b.hole.p1 - b.hole.p0;
    if (axis.norm() == 0) continue;
    const Vec3 w = axis.normalized();
    const Vec3 u = w.unitOrthogonal(), v = w.cross(u);
    const int base = int(m.vertices.size());
    m.vertices.push_back(b.hole.p0);
    m.vertices.push_back(b.hole.p1);
    for (int k = 0; k < kSides; ++k) {
      const double a = 2 * 3.14159265358979323846 * k / kSides;
      const Vec3 off = b.hole.radius * (std::cos(a) * u + std::sin(a) * v);
      m.vertices.push_back(b.hole.p0 + off);
      m.vertices.push_back(b.hole.p1 + off);
    }
    for (int k = 0; k < kSides; ++k) {
      const int i0 = base + 2 + 2 * k, i1 = base + 2 + 2 * ((k + 1) % kSides);
      m.triangles.push_back({base, i1, i0});              // start cap
      m.triangles.push_back({base + 1, i0 + 1, i1 + 1});  // end cap
      m.triangles.push_back({i0, i1, i1 + 1});            // side
      m.triangles.push_back({i0, i1 + 1, i0 + 1});
    }
  }
  std::string tmp = path;
  tmp += ".tmp";
  mesh::write_stl(tmp, m);
  std::rename(tmp.c_str(), path.c_str());
}

}  // namespace mtcs::mold
