#include "mtcs/mold/layout_io.h"

#include <yaml-cpp/yaml.h>

#include <cmath>
#include <fstream>

#include "mtcs/io/atomic_file.h"
#include "mtcs/io/number_text.h"
#include "mtcs/mesh/mesh_io.h"
#include "mtcs/io/yaml_reader.h"

namespace mtcs::mold {

using io::YamlReader;
using io::indexed;

using geometry::Vec3;

Genome load_layout(const std::string& path, const MoldSpec& spec) {
  const YamlReader r(path);
  const YAML::Node root = r.load();
  r.expect_map(root, "", {"circuits"});
  if (!root["circuits"]) r.fail(root, "circuits", "a layout needs a list of circuits");
  const YAML::Node& cs = root["circuits"];
  r.expect_sequence(cs, "circuits");
  Genome g;
  for (std::size_t c = 0; c < cs.size(); ++c) {
    const std::string cp = indexed("circuits", c);
    r.expect_map(cs[c], cp, {"diameter", "waypoints"});
    if (!cs[c]["diameter"] || !cs[c]["waypoints"]) r.fail(cs[c], cp, "a circuit needs diameter and waypoints");
    Circuit circuit;
    circuit.diameter = r.number(cs[c]["diameter"], cp + ".diameter", 1e-9, 1e9);
    bool listed = false;
    for (const double d : spec.drilling.diameters) listed = listed || std::abs(d - circuit.diameter) <= 1e-9 * d;
    if (!listed) r.fail(cs[c]["diameter"], cp + ".diameter", "not one of drilling.diameters of the mold spec");
    const YAML::Node& w = cs[c]["waypoints"];
    r.expect_sequence(w, cp + ".waypoints");
    if (w.size() < 2) r.fail(w, cp + ".waypoints", "a circuit needs at least an inlet and an outlet");
    for (std::size_t i = 0; i < w.size(); ++i)
      circuit.waypoints.push_back(r.vec3(w[i], indexed(cp + ".waypoints", i)));
    g.circuits.push_back(std::move(circuit));
  }
  return g;
}

void save_layout(const std::string& path, const Genome& genome) {
  YAML::Emitter out;
  out.SetDoublePrecision(17);
  out << YAML::BeginMap << YAML::Key << "circuits" << YAML::Value << YAML::BeginSeq;
  for (const Circuit& c : genome.circuits) {
    out << YAML::BeginMap << YAML::Key << "diameter" << YAML::Value << io::shortest(c.diameter);
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
  out << "name,circuit,segment,p0x,p0y,p0z,p1x,p1y,p1z,diameter,entry_face,plugged,dead_end\n";
  for (const Bore& b : layout.bores) {
    out << b.name() << ',' << b.circuit << ',' << b.segment << ',' << n(b.hole.p0.x()) << ',' << n(b.hole.p0.y()) << ','
        << n(b.hole.p0.z()) << ',' << n(b.hole.p1.x()) << ',' << n(b.hole.p1.y()) << ',' << n(b.hole.p1.z()) << ','
        << n(b.diameter) << ',' << to_string(b.entry_face) << ',' << (b.plugged ? 1 : 0) << ',' << n(b.dead_end) << '\n';
  }
  file.commit();
}

void save_holes_csv(const std::string& path, const Layout& layout) {
  io::AtomicFile file(path);
  auto& out = file.stream();
  const auto n = [](double v) { return io::shortest(v); };
  out << "hole,circuit,entry_x,entry_y,entry_z,direction_x,direction_y,direction_z,diameter,depth,entry_face,"
         "plug_x,plug_y,plug_z\n";
  for (const Bore& b : layout.bores) {
    const Vec3 axis = b.hole.p1 - b.hole.p0;
    const double depth = axis.norm();
    const Vec3 u = depth > 0 ? Vec3(axis / depth) : Vec3::Zero();
    // Directions along an axis print as 1, 0, -1; others to a millionth.
    const auto dir = [&](double v) { return n(std::round(v * 1e6) / 1e6); };
    out << b.name() << ',' << b.circuit << ',' << n(b.hole.p0.x()) << ',' << n(b.hole.p0.y()) << ',' << n(b.hole.p0.z())
        << ',' << dir(u.x()) << ',' << dir(u.y()) << ',' << dir(u.z()) << ',' << n(b.diameter) << ',' << n(depth) << ','
        << to_string(b.entry_face);
    if (b.plugged) out << ',' << n(b.hole.p0.x()) << ',' << n(b.hole.p0.y()) << ',' << n(b.hole.p0.z()) << '\n';
    else out << ",,,\n";
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
