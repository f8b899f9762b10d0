// mtcs interfere: component-vs-component interference of two meshes, as the source paper
// reports it: the intersecting triangle pairs grouped by solid and face, the nesting check, the
// distance when apart, and a coloured PLY of both meshes.

#include <CLI/CLI.hpp>
#include <cstdio>
#include <iostream>
#include <memory>

#include "mtcs/cli/commands.h"
#include "mtcs/io/atomic_file.h"
#include "mtcs/io/input_error.h"
#include "mtcs/mesh/interference.h"
#include "mtcs/mesh/interference_report.h"
#include "mtcs/mesh/interference_view.h"
#include "mtcs/mesh/mesh_check.h"
#include "mtcs/mesh/mesh_io.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/report/interference_page.h"
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
  const run::Session session(mold_path, {}, eval::PipelineScope::constraints);
  const run::LayoutInterference r =
      run::layout_interference(session.pipeline(), session.read_layout(layout_path));
  if (json) run::write_layout_interference_json(std::cout, r, mold_path, layout_path);
  else run::write_layout_interference_text(std::cout, r);
  return 0;
}

}  // namespace

Command add_interfere_command(CLI::App& app) {
  struct Options {
    std::string a, b, out, layout, page;
    std::vector<double> translate{0, 0, 0};
    double touch_tolerance = -1;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "interfere",
      "Interference of two solid components as closed meshes (STL, OFF, OBJ, PLY, STEP, IGES): every\n"
      "intersecting triangle pair with its segment (exact test), the pairs and overlap depth per\n"
      "solid and face (near-planar patch), nesting, the distance between the surfaces when apart.\n"
      "Surfaces in contact are not interference unless the solids overlap beyond the touch tolerance.\n"
      "With --layout, A is a mold spec instead: every bore of the layout against the part, each\n"
      "keep-out and the other bores (exact solid-cylinder distances), each bore that crosses one\n"
      "or comes closer than its clearance listed with the distance and the place.");
  sub->footer(
      "Examples:\n"
      "  mtcs interfere slide.stl lock.stl\n"
      "  mtcs interfere core.off pin.off --translate 0,0,12.5 --out report.ply\n"
      "  mtcs interfere a.stl b.stl --touch-tolerance 0.01 --json > report.json\n"
      "  mtcs interfere core.off pin.off --report interference.html\n"
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
  sub->add_option("--report", o->page, "write an HTML page: both components, the interfering triangles, the pairs by solid and face");
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
            const auto groups = mesh::group_by_face(report, a, b, pa, pb);
            if (!o->page.empty()) {
              io::AtomicFile file(o->page);
              file.stream() << mtcs::report::interference_page({o->a, o->b, o->translate, tolerance}, a, b, report, pa, pb, groups);
              file.commit();
            }
            if (o->json) {
              mesh::write_interference_json(std::cout, {o->a, o->b, o->translate, tolerance}, a, b, report, pa, pb, groups);
              return 0;
            }
            mesh::write_interference_text(std::cout, {o->a, o->b, o->translate, tolerance}, a, b, report, pa, pb, groups);
            for (const std::string& f : {o->out, o->page})
              if (!f.empty()) std::printf("wrote %s\n", f.c_str());
            return 0;
          }};
}

}  // namespace mtcs::cli
