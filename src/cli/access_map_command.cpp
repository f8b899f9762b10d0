// mtcs access-map: the accessibility map of a case file (shared/cases/access_maps format),
// written back as the same file with its `collisions` and `am` computed; or of a user's mesh,
// pivot and tool (a bore or cylinders from YAML), written as CSV of directions or a PNG.

#include <CLI/CLI.hpp>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <memory>

#include "mtcs/cli/commands.h"
#include "mtcs/io/atomic_file.h"
#include "mtcs/voxel/access_case.h"
#include "mtcs/voxel/part_map.h"
#include "number_checks.h"
#include "mtcs/report/python_plot.h"

namespace mtcs::cli {

namespace {

// A bad command-line value: the message names the option.
struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct PartOptions {
  std::string mesh, tool, out, method = "aica";
  std::vector<double> pivot, bore, am{64, 64};
  int grid = 128, threads = 0;
};

// The user form: mesh, pivot, tool -> share of free directions, and the map as CSV or PNG.
int run_part_map(const PartOptions& o) {
  const std::vector<double>& p = o.pivot;
  const std::vector<double>& am = o.am;
  if (p.size() != 3) throw UsageError("--pivot: expected x,y,z");
  if (am[0] != std::floor(am[0]) || am[1] != std::floor(am[1]) || am[0] < 1 || am[1] < 1 || am[0] > 4096 || am[1] > 4096)
    throw UsageError("--am: rows and cols must be whole numbers from 1 to 4096, got '" + join_numbers(am) + "'");
  if (o.bore.empty() == o.tool.empty()) throw UsageError("give exactly one of --bore radius,length and --tool TOOL.yaml");
  voxel::Tool tool;
  if (!o.bore.empty()) {
    const std::vector<double>& b = o.bore;
    if (b[0] < 0 || b[1] < 0) throw UsageError("--bore: radius and length must be >= 0, got '" + join_numbers(b) + "'");
    tool = voxel::bore_tool(b[0], b[1]);
  } else {
    tool = voxel::read_tool_file(o.tool);
  }
  if (const std::string problem = voxel::tool_problem(tool); !problem.empty()) throw UsageError("tool: " + problem);
  const std::string ext = std::filesystem::path(o.out).extension().string();
  if (!o.out.empty() && ext != ".csv" && ext != ".png") throw UsageError("--out: expected a .csv or .png file, got '" + o.out + "'");

  const mesh::TriangleMesh part = voxel::read_part(o.mesh);

  voxel::AmOptions options;
  options.threads = o.threads;
  options.method = voxel::parse_am_method(o.method);
  const voxel::SphereGrid sphere{int(am[0]), int(am[1])};
  const voxel::Vec3 pivot(p[0], p[1], p[2]);
  const voxel::PartMap r = voxel::part_access_map(part, o.grid, pivot, tool, sphere, options);
  if (r.pivot_inside) throw UsageError("--pivot " + join_numbers(p) + " lies inside the part (give a point outside it)");

  const long free = long(r.map.cells.size()) - r.map.collisions();
  std::cout << "free directions: " << free << " of " << r.map.cells.size() << " (" << std::fixed << std::setprecision(2)
            << 100.0 * double(free) / double(r.map.cells.size()) << " %); grid " << o.grid << "^3 of " << std::setprecision(6)
            << r.grid.voxel_size << " mm voxels, " << r.solid_voxels << " solid\n";
  if (o.out.empty()) return 0;

  const bool png = ext == ".png";
  const std::string csv_path = png ? o.out + ".csv" : o.out;
  io::AtomicFile file(csv_path);
  voxel::write_map_csv(file.stream(), r.map, sphere);
  file.commit();
  if (png) {
    const std::string title = std::filesystem::path(o.mesh).filename().string() + ", pivot " + join_numbers(p);
    if (report::render_plot("plot_access_map.py", {csv_path, o.out, title}, std::cerr)) std::filesystem::remove(csv_path);
  }
  return 0;
}

}  // namespace

Command add_access_map_command(CLI::App& app) {
  struct Options {
    std::string case_file, mesh, out, method = "aica";
    int threads = 0;
  };
  auto opt = std::make_shared<Options>();
  auto part = std::make_shared<PartOptions>();
  CLI::App* sub = app.add_subcommand(
      "access-map",
      "Accessibility map of a tool (coaxial solid cylinders) pivoting at a point against the solid\n"
      "voxels of a part: which directions of a sphere grid touch no voxel. Every method gives the\n"
      "exact map. Two forms:\n"
      "  --case FILE: a case file (format: tests/data/access_maps/README.md), written back to --out\n"
      "    with its `collisions` and `am` lines computed (1 = collision).\n"
      "  MESH --pivot x,y,z (--bore radius,length | --tool TOOL.yaml): the closed mesh voxelised on\n"
      "    a grid of N^3 cubic voxels fitted to its bounding box (voxel size = largest extent /\n"
      "    (N - 2), the box centred, so one empty layer pads every side); a voxel is solid iff its\n"
      "    centre is strictly inside. The bore is one cylinder from the pivot (radius, length); a\n"
      "    tool file is a YAML list of cylinders {a, b, r}: from a to b along the axis from the\n"
      "    pivot, radius r (mesh units). Prints the share of free directions; --out writes the\n"
      "    map as CSV (phi,gamma,dx,dy,dz,free: phi from +z and gamma about z in degrees, cell\n"
      "    centres, unit direction, free = 1 when the tool touches no solid voxel) or as a PNG\n"
      "    heat map (python3 with matplotlib). The pivot must lie outside the part.");
  sub->footer(
      "Examples:\n"
      "  mtcs access-map --case tests/data/access_maps/drilling_homer_p00.txt --out am.txt\n"
      "  mtcs access-map --case case.txt --mesh part.off --out am.txt --method checkbox --threads 1\n"
      "  mtcs access-map part.off --pivot 0,0,30 --bore 4,60 --grid 128 --am 64,64 --out am.png\n"
      "  mtcs access-map part.off --pivot 0,0,30 --tool tool.yaml --out am.csv\n"
      "    (tool.yaml: [{a: 0, b: 40, r: 2}, {a: 40, b: 80, r: 10}])");
  sub->add_option("mesh", part->mesh, "closed mesh (OFF, STL, OBJ, PLY) for the user form")->check(CLI::ExistingFile);
  sub->add_option("--case", opt->case_file, "case file")->check(CLI::ExistingFile);
  sub->add_option("--mesh", opt->mesh, "mesh to use instead of the case's `mesh` line");
  sub->add_option("--out", opt->out, "--case: output case file; MESH: am.csv or am.png (written whole or not at all)");
  add_numbers(sub, "--pivot", part->pivot, 3, "x,y,z", "the point the tool pivots about (MESH form)");
  add_numbers(sub, "--bore", part->bore, 2, "radius,length", "a straight bore from the pivot (MESH form)");
  sub->add_option("--tool", part->tool, "YAML list of cylinders {a, b, r} (MESH form)")->check(CLI::ExistingFile);
  sub->add_option("--grid", part->grid, "voxels per side of the cubic grid (MESH form)")->capture_default_str()->check(CLI::Range(3, 1024));
  add_numbers(sub, "--am", part->am, 2, "rows,cols", "the sphere grid (MESH form)")->default_str("64,64");
  sub->add_option("--method", opt->method, "aica (default), ica or checkbox")->check(CLI::IsMember({"aica", "ica", "checkbox"}));
  sub->add_option("--threads", opt->threads, "worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
  return {sub, [opt, part] {
            if (opt->case_file.empty() == part->mesh.empty()) {
              std::cerr << "mtcs: access-map: give either --case FILE or a MESH (see mtcs access-map --help)\n";
              return 2;
            }
            if (!part->mesh.empty()) {
              if (!opt->mesh.empty()) {
                std::cerr << "mtcs: access-map: --mesh belongs to the --case form\n";
                return 2;
              }
              part->out = opt->out;
              part->threads = opt->threads;
              part->method = opt->method;
              try {
                return run_part_map(*part);
              } catch (const UsageError& e) {
                std::cerr << "mtcs: access-map: " << e.what() << "\n";
                return 2;
              }
            }
            if (opt->out.empty() || !part->pivot.empty() || !part->bore.empty() || !part->tool.empty()) {
              std::cerr << "mtcs: access-map: --case needs --out and takes no --pivot, --bore or --tool\n";
              return 2;
            }
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
