// mtcs clearance: distance from solid cylinders (bores) to the solid bounded by a closed mesh.

#include <CLI/CLI.hpp>
#include <limits>
#include <memory>

#include "mtcs/cli/commands.h"
#include "mtcs/io/atomic_file.h"
#include "mtcs/io/cylinders_csv.h"
#include "mtcs/io/input_error.h"
#include "mtcs/mesh/bvh.h"
#include "mtcs/mesh/mesh_io.h"
#include "number_checks.h"

namespace mtcs::cli {

Command add_clearance_command(CLI::App& app) {
  struct Options {
    std::string mesh, cylinders, out;
    double upper_bound = std::numeric_limits<double>::infinity();
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "clearance",
      "Exact distance from solid cylinders (bores, flat ends) to the solid bounded by a closed\n"
      "triangle mesh (STL, OFF, OBJ or PLY): 0 when a cylinder touches the part, crosses it or\n"
      "lies inside it.\n"
      "Input columns (by header name, extra columns ignored): id,p0x,p0y,p0z,p1x,p1y,p1z,r\n"
      "  (axis end points = end disk centres, radius; the mesh's own coordinates), or name and\n"
      "  diameter instead of id and r: the bores.csv of mtcs optimize reads as it is.\n"
      "Output: id,distance,bounded  (bounded=1: only distance >= U was proved; the value is a\n"
      "lower bound >= U).");
  sub->footer(
      "Examples:\n"
      "  mtcs clearance part.off --cylinders bores.csv --out clearance.csv\n"
      "  mtcs clearance part.stl --cylinders bores.csv --out check.csv --upper-bound 4\n"
      "      (only bores closer than 4 get exact distances: the clearance check, faster)");
  sub->add_option("MESH", opt->mesh, "closed, outward-oriented triangle mesh")->required()->check(CLI::ExistingFile);
  sub->add_option("--cylinders", opt->cylinders, "input CSV of cylinders")->required()->check(CLI::ExistingFile);
  sub->add_option("--out", opt->out, "output CSV (written whole or not at all)")->required();
  sub->add_option("--upper-bound", opt->upper_bound,
                  "U: distances >= U may stop early and be reported as bounded (default: none)")
      ->check(positive_number());

  return {sub, [opt] {
            mesh::TriangleMesh part;
            try {
              part = mesh::read_mesh(opt->mesh);
            } catch (const mesh::MeshError& e) {
              throw io::InputError(opt->mesh, 0, 0, "", e.what());
            }
            // A distance "to the solid" needs a solid: inside/outside is decided by ray parity.
            if (const std::string problem = mesh::closed_mesh_problem(part); !problem.empty())
              throw io::InputError(opt->mesh, 0, 0, "", "not a closed mesh: " + problem);
            const auto cylinders = io::read_cylinders_csv(opt->cylinders);
            const mesh::TriangleBvh bvh(part);
            io::AtomicFile file(opt->out);
            auto& out = file.stream();
            out.precision(17);
            out << "id,distance,bounded\n";
            for (const auto& c : cylinders) {
              const auto r = mesh::cylinder_clearance(bvh, c.cylinder, opt->upper_bound);
              out << c.id << ',' << r.distance << ',' << (r.bounded ? 1 : 0) << '\n';
            }
            file.commit();
            return 0;
          }};
}

}  // namespace mtcs::cli
