// mtcs interfere: component-vs-component interference of two meshes, as the source paper
// reports it: the intersecting triangle pairs grouped by solid and face, the nesting check, the
// distance when apart, and a coloured PLY of both meshes.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>

#include "mtcs/cli/commands.h"
#include "mtcs/io/atomic_file.h"
#include "mtcs/io/input_error.h"
#include "mtcs/mesh/interference.h"
#include "mtcs/mesh/interference_view.h"
#include "mtcs/mesh/mesh_check.h"
#include "mtcs/mesh/mesh_io.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/run/layout_interference.h"
#include "mtcs/run/session.h"

namespace mtcs::cli {
namespace {

using mesh::TriangleMesh;

TriangleMesh load_solid(const std::string& path) {
  TriangleMesh m;
  try {
    m = mesh::read_mesh(path);
  } catch (const mesh::MeshError& e) {
    throw io::InputError(path, 0, 0, "", e.what());
  }
  if (const auto check = mesh::check_mesh(m); !check.ok())
    throw io::InputError(path, 0, 0, "", "not the closed, oriented, self-intersection-free surface of a solid: " + check.message());
  return m;
}

// A layout's bores against the mold (--layout): the run module's report, as text or JSON.
int print_layout_interference(const std::string& mold_path, const std::string& layout_path, bool json) {
  const run::Session session(mold_path);
  const run::LayoutInterference r =
      run::layout_interference(session.pipeline(), mold::load_layout(layout_path, session.spec()));
  if (json) {
    nlohmann::ordered_json out;
    out["mold"] = mold_path;
    out["layout"] = layout_path;
    out["bores"] = r.bores;
    out["against"] = r.against;
    out["pairs"] = r.crossing;  // bore pairs that touch, cross or lie inside each other
    out["distance"] = r.found.empty() ? nlohmann::ordered_json() : nlohmann::ordered_json(r.nearest);
    auto& list = out["violations"] = nlohmann::ordered_json::array();
    for (const auto& v : r.found)
      list.push_back({{"kind", eval::to_string(v.kind)},
                      {"bore", v.elements.at(0)},
                      {"against", v.elements.size() > 1 ? v.elements[1] : ""},
                      {"interferes", v.distance <= 0},
                      {"distance", v.distance},
                      {"clearance", v.margin},
                      {"where", {v.where.x(), v.where.y(), v.where.z()}}});
    std::cout << out.dump(2) << "\n";
    return 0;
  }
  std::cout << r.bores << " bores against ";
  for (std::size_t i = 0; i < r.against.size(); ++i) std::cout << (i ? ", " : "") << r.against[i];
  std::cout << (r.against.empty() ? "each other" : " and each other") << ": " << r.crossing << " interfering, "
            << r.found.size() - std::size_t(r.crossing) << " closer than their clearance\n";
  if (r.found.empty()) return 0;
  std::cout << "\n" << std::left << std::setw(13) << "kind" << std::setw(10) << "bore" << std::setw(18) << "against"
            << std::right << std::setw(12) << "distance" << std::setw(11) << "clearance" << "  where\n";
  for (const auto& v : r.found) {
    std::cout << std::left << std::setw(13) << eval::to_string(v.kind) << std::setw(10) << v.elements.at(0) << std::setw(18)
              << (v.elements.size() > 1 ? v.elements[1] : "") << std::right << std::fixed << std::setprecision(4)
              << std::setw(12) << v.distance << std::setw(11) << v.margin << "  (" << std::setprecision(3)
              << v.where.x() << ", " << v.where.y() << ", " << v.where.z() << ")"
              << (v.distance <= 0 ? "  INTERFERES" : "") << "\n";
    std::cout.unsetf(std::ios::fixed);
  }
  return 0;
}

}  // namespace

Command add_interfere_command(CLI::App& app) {
  struct Options {
    std::string a, b, out, layout;
    std::vector<double> translate{0, 0, 0};
    double touch_tolerance = -1;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "interfere",
      "Interference of two solid components given as closed meshes (STL, OFF, OBJ, PLY):\n"
      "every intersecting triangle pair with its intersection segment (exact test), the pairs\n"
      "per solid (connected component) and face (near-planar patch), whether one solid lies\n"
      "inside the other, and the distance between the surfaces when they do not meet.\n"
      "Surfaces in contact (e.g. plates face to face) are not interference unless the solids\n"
      "overlap by more than the touch tolerance.\n"
      "With --layout, A is a mold spec instead: every bore of the layout against the part, each\n"
      "keep-out and the other bores (exact solid-cylinder distances), each bore that crosses one\n"
      "or comes closer than its clearance listed with the distance and the place.");
  sub->footer(
      "Examples:\n"
      "  mtcs interfere slide.stl lock.stl\n"
      "  mtcs interfere core.off pin.off --translate 0,0,12.5 --out report.ply\n"
      "  mtcs interfere a.stl b.stl --touch-tolerance 0.01 --json > report.json\n"
      "  mtcs interfere molds/cup.yaml --layout molds/cup.layout.yaml\n"
      "Each mesh must bound a solid: closed, manifold, consistently oriented, no self-intersection.\n"
      "Exit codes: 0 done (whether or not they interfere), 2 bad input (file and reason printed).");
  sub->add_option("a", o->a, "mesh of component A (with --layout: the mold spec)")->required();
  sub->add_option("b", o->b, "mesh of component B (not with --layout)");
  sub->add_option("--layout", o->layout, "check this layout's bores against the mold A (YAML)");
  sub->add_option("--translate", o->translate, "move B by tx,ty,tz before the check")->delimiter(',')->expected(3);
  sub->add_option("--touch-tolerance", o->touch_tolerance,
                  "overlap up to this depth counts as contact, not interference\n"
                  "(default: 1e-9 x the diagonal of both meshes' bounding box; 0: every contact counts)")
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--out", o->out, "write both meshes as PLY: interfering triangles red, contacts yellow");
  sub->add_flag("--json", o->json, "print a JSON object (pairs, distance, groups, nesting) instead of text");

  return {sub, [o] {
            if (!o->layout.empty()) {
              if (!o->b.empty()) throw io::InputError(o->b, 0, 0, "", "with --layout, give the mold spec alone");
              return print_layout_interference(o->a, o->layout, o->json);
            }
            if (o->b.empty()) throw io::InputError(o->a, 0, 0, "", "a second mesh (B) to check against, or --layout");
            const TriangleMesh a = load_solid(o->a);
            TriangleMesh b = load_solid(o->b);
            b.translate({o->translate[0], o->translate[1], o->translate[2]});
            const auto ba = a.bounds(), bb = b.bounds();
            const double diagonal = (ba.max.cwiseMax(bb.max) - ba.min.cwiseMin(bb.min)).norm();
            const double tolerance = o->touch_tolerance >= 0 ? o->touch_tolerance : 1e-9 * diagonal;
            const auto report = mesh::interfere(a, b, tolerance);
            const auto pa = mesh::split_parts(a), pb = mesh::split_parts(b);
            if (!o->out.empty()) {
              io::AtomicFile file(o->out);
              mesh::write_interference_ply(file.stream(), a, b, report);
              file.commit();
            }
            const auto groups = mesh::group_by_face(report, pa, pb);
            auto point = [](const geometry::Vec3& v) { return nlohmann::json::array({v.x(), v.y(), v.z()}); };
            if (o->json) {
              nlohmann::json j;
              j["a"] = o->a, j["b"] = o->b, j["translate"] = o->translate;
              j["touch_tolerance"] = tolerance;
              j["interferes"] = report.interferes;
              j["distance"] = report.distance;
              j["pair_count"] = report.pairs.size();
              j["penetrating_pairs"] = report.penetrating;
              j["solids_of_a_inside_b"] = report.solids_of_a_inside_b;
              j["solids_of_b_inside_a"] = report.solids_of_b_inside_a;
              j["pairs"] = nlohmann::json::array();
              for (const auto& p : report.pairs)
                j["pairs"].push_back({{"a", p.a}, {"b", p.b}, {"solid_a", pa.solid_of[std::size_t(p.a)]},
                                      {"face_a", pa.face_of[std::size_t(p.a)]}, {"solid_b", pb.solid_of[std::size_t(p.b)]},
                                      {"face_b", pb.face_of[std::size_t(p.b)]}, {"penetrating", p.penetrating},
                                      {"coplanar", p.x.coplanar}, {"segment", {point(p.x.p), point(p.x.q)}}});
              j["groups"] = nlohmann::json::array();
              for (const auto& g : groups)
                j["groups"].push_back({{"solid_a", g.solid_a}, {"face_a", g.face_a}, {"solid_b", g.solid_b},
                                       {"face_b", g.face_b}, {"pairs", g.pairs}, {"penetrating", g.penetrating}});
              std::cout << j.dump(1) << '\n';
              return 0;
            }
            std::printf("A: %s (%zu triangles, %d solid(s), %d faces)\nB: %s (%zu triangles, %d solid(s), %d faces)\n",
                        o->a.c_str(), a.triangles.size(), pa.solids, pa.faces(), o->b.c_str(), b.triangles.size(),
                        pb.solids, pb.faces());
            std::printf("verdict: %s\n", report.interferes ? "INTERFERENCE" : report.pairs.empty() ? "apart" : "contact only");
            std::printf("intersecting triangle pairs: %zu (beyond the touch tolerance %.3g: %zu)\n", report.pairs.size(),
                        tolerance, report.penetrating);
            for (int s : report.solids_of_a_inside_b) std::printf("solid %d of A lies inside B\n", s);
            for (int s : report.solids_of_b_inside_a) std::printf("solid %d of B lies inside A\n", s);
            if (report.pairs.empty() && !report.interferes) std::printf("distance: %.17g\n", report.distance);
            if (!groups.empty()) std::printf("pairs per face (solid.face of A x solid.face of B: pairs, interfering):\n");
            for (const auto& g : groups)
              std::printf("  A %d.%d x B %d.%d: %d, %d\n", g.solid_a, g.face_a, g.solid_b, g.face_b, g.pairs, g.penetrating);
            if (!report.pairs.empty()) std::printf("pairs (triangle of A, triangle of B, interfering, segment):\n");
            for (const auto& p : report.pairs)
              std::printf("  %d %d %d  %.9g %.9g %.9g  %.9g %.9g %.9g\n", p.a, p.b, int(p.penetrating), p.x.p.x(), p.x.p.y(),
                          p.x.p.z(), p.x.q.x(), p.x.q.y(), p.x.q.z());
            if (!o->out.empty()) std::printf("wrote %s\n", o->out.c_str());
            return 0;
          }};
}

}  // namespace mtcs::cli
