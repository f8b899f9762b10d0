// mtcs bench access-map: per method the median and p90 ms per map, the ICA efficiency over all
// node tests and the cells differing from CheckBox; the median over cases of CheckBox's time
// over AICA's.

#include "bench_access_map.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <map>
#include <memory>

#include "mtcs/io/input_error.h"
#include "mtcs/mesh/mesh_io.h"
#include "mtcs/voxel/access_case.h"

namespace mtcs::bench {

namespace fs = std::filesystem;
using namespace mtcs::voxel;

namespace {

double thread_ms() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}
double wall_ms() { return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// The case's mesh: under --mesh-root as the case names it (shared/molds_data/X.off), else by
// its file name alone (a flat folder of meshes such as tests/data/meshes).
std::string case_mesh_path(const AccessCase& c, const std::string& mesh_root) {
  if (mesh_root.empty()) return resolve_case_mesh(c);
  const fs::path nested = fs::path(mesh_root) / c.mesh;
  if (fs::exists(nested)) return nested.string();
  return (fs::path(mesh_root) / fs::path(c.mesh).filename()).string();
}

// Octrees by mesh, scale, centre and grid: the cases of one mesh share one.
const Octree& shared_octree(const AccessCase& c, const std::string& mesh_path) {
  static std::map<std::string, std::unique_ptr<Octree>> cache;
  char key[512];
  std::snprintf(key, sizeof key, "%s|%.17g|%.17g,%.17g,%.17g|%d,%d,%d|%.17g|%.17g,%.17g,%.17g", mesh_path.c_str(), c.scale,
                c.centre.x(), c.centre.y(), c.centre.z(), c.grid.size[0], c.grid.size[1], c.grid.size[2], c.grid.voxel_size,
                c.grid.origin.x(), c.grid.origin.y(), c.grid.origin.z());
  auto& slot = cache[key];
  if (!slot) slot = std::make_unique<Octree>(case_octree(c, mesh_path));
  return *slot;
}

struct MethodTotals {
  std::vector<double> ms;
  std::uint64_t node_tests = 0, checkbox_calls = 0;
  long differing = 0;
  double efficiency() const { return node_tests == 0 ? 1.0 : 1.0 - double(checkbox_calls) / double(node_tests); }
};

}  // namespace

double time_access_map(const Octree& tree, const Vec3& pivot, const Tool& tool, const SphereGrid& sphere, const AmOptions& o,
                       AccessMap* out, int reps) {
  double best = 1e300;
  const auto clock = o.threads == 1 ? thread_ms : wall_ms;
  for (int r = 0; r < reps; ++r) {
    const double t0 = clock();
    AccessMap m = compute_access_map(tree, pivot, tool, sphere, o);
    best = std::min(best, clock() - t0);
    if (out) *out = std::move(m);
  }
  return best;
}

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const double pos = q * double(v.size() - 1);
  const std::size_t i = std::size_t(pos);
  return i + 1 < v.size() ? v[i] + (pos - double(i)) * (v[i + 1] - v[i]) : v[i];
}

long differing_cells(const AccessMap& a, const AccessMap& b) {
  long diff = 0;
  for (std::size_t k = 0; k < a.cells.size(); ++k) diff += a.cells[k] != b.cells[k];
  return diff;
}

int bench_access_map(const AccessMapBenchOptions& opt) {
  std::vector<std::string> paths;
  for (const auto& e : fs::directory_iterator(opt.cases))
    if (e.path().extension() == ".txt") paths.push_back(e.path().string());
  std::sort(paths.begin(), paths.end());
  if (paths.empty()) throw io::InputError(opt.cases, 0, 0, "--cases", "no case files (*.txt) in the folder");

  const AmMethod methods[] = {AmMethod::aica, AmMethod::ica, AmMethod::checkbox};
  std::map<AmMethod, MethodTotals> totals;
  std::map<AmMethod, std::vector<double>> speedup;  // CheckBox's ms over the method's, per case
  long against_case = 0, cases_with_map = 0;  // CheckBox cells differing from the case files' `am`
  for (const std::string& path : paths) {
    const AccessCase c = read_access_case(path);
    const Octree& tree = shared_octree(c, case_mesh_path(c, opt.mesh_root));
    if (tree.touches_solid(c.pivot))
      throw io::InputError(c.path, c.pivot_line, 1, "pivot", "the pivot lies inside the part (in a solid voxel)");
    const SphereGrid sphere = opt.am_rows > 0 ? SphereGrid{opt.am_rows, opt.am_cols} : c.sphere;
    AccessMap reference;
    std::map<AmMethod, double> ms;
    for (AmMethod m : {AmMethod::checkbox, AmMethod::ica, AmMethod::aica}) {
      AmOptions o;
      o.method = m;
      o.threads = opt.threads;
      AccessMap map;
      ms[m] = time_access_map(tree, c.pivot, c.tool, sphere, o, &map, opt.repeat);
      if (m == AmMethod::checkbox) {
        reference = map;
        if (!c.am.empty() && opt.am_rows == 0) {  // the case file's own map, an outside check
          const std::vector<std::string> rows = map.rows();
          for (std::size_t i = 0; i < rows.size(); ++i)
            for (std::size_t j = 0; j < rows[i].size(); ++j)
              against_case += i >= c.am.size() || j >= c.am[i].size() || rows[i][j] != c.am[i][j];
          ++cases_with_map;
        }
      }
      MethodTotals& t = totals[m];
      t.ms.push_back(ms[m]);
      t.node_tests += map.stats.node_tests;
      t.checkbox_calls += map.stats.checkbox_calls;
      t.differing += differing_cells(map, reference);
    }
    for (AmMethod m : methods) speedup[m].push_back(ms[AmMethod::checkbox] / ms[m]);
  }

  const double median_speedup = quantile(speedup[AmMethod::aica], 0.5);
  const MethodTotals& aica = totals[AmMethod::aica];
  if (opt.json) {
    std::printf("{\"cases\": %zu, \"threads\": %d, \"repeat\": %d, \"median_speedup_vs_checkbox\": %.4f, "
                "\"ica_efficiency\": %.6f, \"differing_cells\": %ld, "
                "\"cases_with_map\": %ld, \"checkbox_cells_differing_from_cases\": %ld, \"methods\": [",
                paths.size(), opt.threads, opt.repeat, median_speedup, aica.efficiency(),
                aica.differing + totals[AmMethod::ica].differing, cases_with_map, against_case);
    for (std::size_t i = 0; i < 3; ++i) {
      const MethodTotals& t = totals[methods[i]];
      std::printf("%s\n  {\"method\": \"%s\", \"median_ms\": %.5f, \"p90_ms\": %.5f, \"node_tests\": %llu, \"checkbox_calls\": %llu, "
                  "\"ica_efficiency\": %.6f, \"differing_cells\": %ld, \"median_speedup_vs_checkbox\": %.4f}",
                  i ? "," : "", to_string(methods[i]).c_str(), quantile(t.ms, 0.5), quantile(t.ms, 0.9),
                  (unsigned long long)t.node_tests, (unsigned long long)t.checkbox_calls, t.efficiency(), t.differing,
                  quantile(speedup[methods[i]], 0.5));
    }
    std::printf("\n]}\n");
    return 0;
  }
  std::fprintf(stderr, "CheckBox cells differing from the %ld case files' maps: %ld\n", cases_with_map, against_case);
  std::printf("method,cases,median_ms,p90_ms,node_tests,checkbox_calls,ica_efficiency,differing_cells,median_speedup_vs_checkbox\n");
  for (AmMethod m : methods) {
    const MethodTotals& t = totals[m];
    std::printf("%s,%zu,%.4f,%.4f,%llu,%llu,%.6f,%ld,%.4f\n", to_string(m).c_str(), paths.size(), quantile(t.ms, 0.5),
                quantile(t.ms, 0.9), (unsigned long long)t.node_tests, (unsigned long long)t.checkbox_calls, t.efficiency(),
                t.differing, quantile(speedup[m], 0.5));
  }
  return 0;
}

}  // namespace mtcs::bench
