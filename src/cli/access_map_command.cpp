// mtcs access-map: the accessibility map of a case file (shared/cases/access_maps format),
// written back as the same file with its `collisions` and `am` computed.

#include <CLI/CLI.hpp>
#include <chrono>
#include <iostream>
#include <memory>

#include "mtcs/cli/commands.h"
#include "mtcs/io/atomic_file.h"
#include "mtcs/voxel/access_case.h"

namespace mtcs::cli {

Command add_access_map_command(CLI::App& app) {
  struct Options {
    std::string case_file, mesh, out, method = "aica";
    int threads = 0;
  };
  auto opt = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "access-map",
      "Accessibility map of a tool (coaxial solid cylinders) pivoting at a point against the solid\n"
      "voxels of a part: which directions of a sphere grid touch no voxel (1 = collision).\n"
      "Reads a case file (format: tests/data/access_maps/README.md) and writes it back with its\n"
      "`collisions` and `am` lines computed. Every method gives the exact map.");
  sub->footer(
      "Examples:\n"
      "  mtcs access-map --case shared/cases/access_maps/drilling_homer_p00.txt --out am.txt\n"
      "  mtcs access-map --case case.txt --mesh part.off --out am.txt --method checkbox --threads 1");
  sub->add_option("--case", opt->case_file, "case file")->required()->check(CLI::ExistingFile);
  sub->add_option("--mesh", opt->mesh, "mesh to use instead of the case's `mesh` line");
  sub->add_option("--out", opt->out, "output case file (written whole or not at all)")->required();
  sub->add_option("--method", opt->method, "aica (default), ica or checkbox")->check(CLI::IsMember({"aica", "ica", "checkbox"}));
  sub->add_option("--threads", opt->threads, "worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
  return {sub, [opt] {
            const voxel::AccessCase c = voxel::read_access_case(opt->case_file);
            voxel::AmOptions options;
            options.method = voxel::parse_am_method(opt->method);
            options.threads = opt->threads;
            const auto t0 = std::chrono::steady_clock::now();
            const voxel::CaseSolution s = voxel::solve_access_case(c, voxel::resolve_case_mesh(c, opt->mesh), options);
            const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
            if ((c.solid_voxels >= 0 && long(s.solid_voxels) != c.solid_voxels) || (c.octree_nodes >= 0 && long(s.octree_nodes) != c.octree_nodes))
              std::cerr << "mtcs: warning: " << s.solid_voxels << " solid voxels and " << s.octree_nodes << " octree nodes, the case says "
                        << c.solid_voxels << " and " << c.octree_nodes << "\n";
            io::AtomicFile file(opt->out);
            voxel::write_access_case(file.stream(), c, s.map.rows());
            file.commit();
            std::cout << opt->method << ": " << s.map.collisions() << " of " << s.map.cells.size() << " cells collide; "
                      << s.solid_voxels << " solid voxels, " << s.octree_nodes << " octree nodes; " << s.map.stats.node_tests
                      << " node tests, " << s.map.stats.checkbox_calls << " CheckBox calls (ICA efficiency "
                      << s.map.stats.ica_efficiency() << "); " << ms << " ms with voxelisation\n";
            return 0;
          }};
}

}  // namespace mtcs::cli
