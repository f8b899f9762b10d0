// Hidden timing run (not part of the suite): AICA, ICA and CheckBox on every public case in one
// run, on one thread; per method the median and p90 ms per map, the ICA efficiency and the cells
// differing from CheckBox; then 64 x 64 drilling maps on 1 and 2 threads.
//   ./build/tests/voxel_tests "[.am_timing]"      (MTCS_AM_TIMING_CSV=FILE writes per-case rows)

#include <catch2/catch.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <random>

#include "mtcs/voxel/accessibility_map.h"
#include "voxel/case_files.h"

using namespace mtcs;
using namespace mtcs::voxel;

namespace {

// CPU time of the calling thread: on one thread the map runs on it (a task_arena of one slot),
// and other processes on a loaded machine do not count. Wall time for more threads.
double thread_ms() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) * 1e3 + double(t.tv_nsec) * 1e-6;
}
double wall_ms() { return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// The best of `reps` runs (ms).
double time_map(const Octree& tree, const AccessCase& c, const SphereGrid& sphere, const AmOptions& o, AccessMap* out, int reps) {
  double best = 1e300;
  const auto clock = o.threads == 1 ? thread_ms : wall_ms;
  for (int r = 0; r < reps; ++r) {
    const double t0 = clock();
    AccessMap m = compute_access_map(tree, c.pivot, c.tool, sphere, o);
    const double ms = clock() - t0;
    best = std::min(best, ms);
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

}  // namespace

TEST_CASE("access-map timing over all public cases", "[.am_timing]") {
  const int reps = std::getenv("MTCS_AM_REPS") ? std::atoi(std::getenv("MTCS_AM_REPS")) : 5;
  const char* csv_path = std::getenv("MTCS_AM_TIMING_CSV");
  std::ofstream csv;
  if (csv_path) {
    csv.open(csv_path);
    csv << "case,method,threads,am,ms,node_tests,checkbox_calls,ica_efficiency,differing_cells\n";
  }
  const AmMethod methods[] = {AmMethod::aica, AmMethod::ica, AmMethod::checkbox};
  std::map<AmMethod, std::vector<double>> ms;
  std::map<AmMethod, std::uint64_t> tests, boxes, differing;
  std::vector<double> speedup;
  for (const auto& path : testing::case_paths()) {
    const AccessCase c = read_access_case(path);
    const Octree& tree = testing::case_octree(c);
    AccessMap reference;
    std::map<AmMethod, double> t;
    for (AmMethod m : {AmMethod::checkbox, AmMethod::ica, AmMethod::aica}) {
      AmOptions o;
      o.method = m;
      o.threads = 1;
      if (const char* memo = std::getenv("MTCS_AM_MEMO_LEVELS")) o.memo_levels = std::atoi(memo);
      if (const char* v = std::getenv("MTCS_AM_SUBVOXEL_LEVELS")) o.subvoxel_levels = std::atoi(v);
      AccessMap map;
      t[m] = time_map(tree, c, c.sphere, o, &map, reps);
      if (m == AmMethod::checkbox) reference = map;
      std::uint64_t diff = 0;
      for (std::size_t k = 0; k < map.cells.size(); ++k) diff += map.cells[k] != reference.cells[k];
      ms[m].push_back(t[m]);
      tests[m] += map.stats.node_tests;
      boxes[m] += map.stats.checkbox_calls;
      differing[m] += diff;
      if (csv_path)
        csv << std::filesystem::path(path).stem().string() << ',' << to_string(m) << ",1,32x32," << t[m] << ',' << map.stats.node_tests << ','
            << map.stats.checkbox_calls << ',' << map.stats.ica_efficiency() << ',' << diff << '\n';
    }
    speedup.push_back(t[AmMethod::checkbox] / t[AmMethod::aica]);
  }
  std::printf("method    median_ms  p90_ms  node_tests  checkbox_calls  ica_efficiency  differing_cells\n");
  for (AmMethod m : methods) {
    const double eff = 1.0 - double(boxes[m]) / double(tests[m]);
    std::printf("%-9s %9.3f %7.3f %11llu %15llu %14.4f %16llu\n", to_string(m).c_str(), quantile(ms[m], 0.5), quantile(ms[m], 0.9),
                (unsigned long long)tests[m], (unsigned long long)boxes[m], eff, (unsigned long long)differing[m]);
  }
  std::printf("AICA speed-up over CheckBox per case: median %.2fx, p10 %.2fx; ratio of medians %.2fx\n", quantile(speedup, 0.5),
              quantile(speedup, 0.1), quantile(ms[AmMethod::checkbox], 0.5) / quantile(ms[AmMethod::aica], 0.5));

  // 64 x 64 drilling maps on the 128^3 grids, 1 and 2 threads.
  for (int threads : {1, 2}) {
    std::map<AmMethod, std::vector<double>> dms;
    for (const auto& path : testing::case_paths()) {
      if (std::filesystem::path(path).filename().string().rfind("drilling_", 0) != 0) continue;
      const AccessCase c = read_access_case(path);
      const Octree& tree = testing::case_octree(c);
      for (AmMethod m : methods) {
        AmOptions o;
        o.method = m;
        o.threads = threads;
        if (const char* memo = std::getenv("MTCS_AM_MEMO_LEVELS")) o.memo_levels = std::atoi(memo);
        if (const char* v = std::getenv("MTCS_AM_SUBVOXEL_LEVELS")) o.subvoxel_levels = std::atoi(v);
      if (const char* v = std::getenv("MTCS_AM_SUBVOXEL_LEVELS")) o.subvoxel_levels = std::atoi(v);
        AccessMap map;
        const double t = time_map(tree, c, SphereGrid{64, 64}, o, &map, threads == 1 ? reps : 3 * reps);
        dms[m].push_back(t);
        if (csv_path)
          csv << std::filesystem::path(path).stem().string() << ',' << to_string(m) << ',' << threads << ",64x64," << t << ','
              << map.stats.node_tests << ',' << map.stats.checkbox_calls << ',' << map.stats.ica_efficiency() << ",\n";
      }
    }
    for (AmMethod m : methods)
      std::printf("drilling 64x64, %d thread(s), %-8s median %.3f ms, p90 %.3f ms, max %.3f ms\n", threads, to_string(m).c_str(),
                  quantile(dms[m], 0.5), quantile(dms[m], 0.9), quantile(dms[m], 1.0));
  }
}

// For profilers: AICA 64 x 64 on every drilling case, one thread, five times.
TEST_CASE("access-map profile loop", "[.am_profile]") {
  const AmMethod m = std::getenv("MTCS_AM_METHOD") ? parse_am_method(std::getenv("MTCS_AM_METHOD")) : AmMethod::aica;
  std::uint64_t tests = 0, boxes = 0;
  for (int rep = 0; rep < (std::getenv("MTCS_AM_REPS") ? std::atoi(std::getenv("MTCS_AM_REPS")) : 5); ++rep)
    for (const auto& path : testing::case_paths()) {
      const char* kind = std::getenv("MTCS_AM_KIND");
      if (std::filesystem::path(path).filename().string().rfind(kind ? kind : "drilling_", 0) != 0) continue;
      const AccessCase c = read_access_case(path);
      AmOptions o;
      o.method = m;
      o.threads = 1;
      if (const char* v = std::getenv("MTCS_AM_SUBVOXEL_LEVELS")) o.subvoxel_levels = std::atoi(v);
      if (const char* v = std::getenv("MTCS_AM_MEMO_LEVELS")) o.memo_levels = std::atoi(v);
      const AccessMap map = compute_access_map(testing::case_octree(c), c.pivot, c.tool, SphereGrid{std::getenv("MTCS_AM_N") ? std::atoi(std::getenv("MTCS_AM_N")) : 64, std::getenv("MTCS_AM_N") ? std::atoi(std::getenv("MTCS_AM_N")) : 64}, o);
      tests += map.stats.node_tests;
      boxes += map.stats.checkbox_calls;
    }
  std::printf("node tests %llu, checkbox calls %llu\n", (unsigned long long)tests, (unsigned long long)boxes);
}

// Hidden scaling run: the first drilling case of each mesh (its pivot and bore) on 128^3 and
// 256^3 grids (same 50 mm cube), maps 32^2 to 128^2, 1 and 2 threads, all three methods;
// cells differing from CheckBox counted.   ./build/tests/voxel_tests "[.am_scaling]"
TEST_CASE("access-map scaling with grid and map size", "[.am_scaling]") {
  std::printf("case,grid,am,threads,method,ms,node_tests,checkbox_calls,ica_efficiency,differing_cells\n");
  for (const char* name : {"drilling_fandisk_large_p00", "drilling_mcad_herringbone_gear_p00", "drilling_homer_p00"}) {
    const AccessCase c = read_access_case(std::string(MTCS_TEST_DATA) + "/access_maps/" + name + ".txt");
    const mesh::TriangleMesh part = testing::case_mesh(c);
    for (int n : {128, 256}) {
      GridSpec g = c.grid;
      g.size = {n, n, n};
      g.voxel_size = 50.0 / n;
      const Octree tree(voxelize(part, g));
      for (int am : {32, 64, 128})
        for (int threads : {1, 2}) {
          AccessMap reference;
          for (AmMethod m : {AmMethod::checkbox, AmMethod::ica, AmMethod::aica}) {
            AmOptions o;
            o.method = m;
            o.threads = threads;
            AccessMap map;
            const double ms = time_map(tree, c, SphereGrid{am, am}, o, &map, m == AmMethod::checkbox ? 1 : 3);
            if (m == AmMethod::checkbox) reference = map;
            long diff = 0;
            for (std::size_t k = 0; k < map.cells.size(); ++k) diff += map.cells[k] != reference.cells[k];
            std::printf("%s,%d,%d,%d,%s,%.3f,%llu,%llu,%.5f,%ld\n", name, n, am, threads, to_string(m).c_str(), ms,
                        (unsigned long long)map.stats.node_tests, (unsigned long long)map.stats.checkbox_calls,
                        map.stats.ica_efficiency(), diff);
            std::fflush(stdout);
          }
        }
    }
  }
}

// Hidden: wall and process CPU time of one 128 x 128 CheckBox map on 1 and 2 threads (does the
// second thread work?).
TEST_CASE("access-map thread check", "[.am_threads]") {
  const AccessCase c = read_access_case(std::string(MTCS_TEST_DATA) + "/access_maps/drilling_homer_p00.txt");
  const Octree& tree = testing::case_octree(c);
  for (int threads : {1, 2}) {
    AmOptions o;
    o.method = AmMethod::checkbox;
    o.threads = threads;
    const std::clock_t c0 = std::clock();
    const double w0 = wall_ms();
    compute_access_map(tree, c.pivot, c.tool, SphereGrid{128, 128}, o);
    std::printf("%d thread(s): wall %.1f ms, process cpu %.1f ms\n", threads, wall_ms() - w0, 1e3 * double(std::clock() - c0) / CLOCKS_PER_SEC);
  }
}

// Hidden: AICA and ICA against CheckBox on random pivots 0.5-25 mm off the three meshes (surface
// point + offset along the face normal), paper tool and random bores, 32 x 32 maps.
//   ./build/tests/voxel_tests "[.am_random]"
TEST_CASE("access-map methods agree on random pivots", "[.am_random]") {
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> U(0, 1);
  long maps = 0, differing = 0, undecided = 0, quad = 0;
  for (const char* name : {"public_fandisk_large_N128_am32_p00", "public_mcad_herringbone_gear_N128_am32_p00", "public_homer_N128_am32_p00"}) {
    const AccessCase c = read_access_case(std::string(MTCS_TEST_DATA) + "/access_maps/" + name + ".txt");
    const mesh::TriangleMesh part = testing::case_mesh(c);
    const Octree& tree = testing::case_octree(c);
    for (int n = 0; n < 60; ++n) {
      const std::size_t t = std::size_t(U(rng) * double(part.triangles.size()));
      double a = U(rng), b = U(rng);
      if (a + b > 1) a = 1 - a, b = 1 - b;
      const Vec3 p0 = part.corner(t, 0), p1 = part.corner(t, 1), p2 = part.corner(t, 2);
      const Vec3 normal = (p1 - p0).cross(p2 - p0).normalized();
      const double offset = n % 2 ? 0.5 + 2 * U(rng) : 8 + 17 * U(rng);
      const Vec3 pivot = p0 + a * (p1 - p0) + b * (p2 - p0) + offset * normal;
      if (tree.touches_solid(pivot)) continue;
      const Tool tool = n % 3 == 0 ? c.tool : Tool{{0, 60 + 60 * U(rng), 2.5 + 3.5 * U(rng)}};
      const AccessMap ref = compute_access_map(tree, pivot, tool, c.sphere, [] { AmOptions o; o.method = AmMethod::checkbox; return o; }());
      undecided += long(ref.stats.undecided);
      quad += long(ref.stats.quad_verdicts);
      for (AmMethod m : {AmMethod::ica, AmMethod::aica}) {
        AmOptions o;
        o.method = m;
        const AccessMap map = compute_access_map(tree, pivot, tool, c.sphere, o);
        for (std::size_t k = 0; k < map.cells.size(); ++k) differing += map.cells[k] != ref.cells[k];
        ++maps;
      }
    }
  }
  std::printf("%ld maps, %ld cells differing from CheckBox; CheckBox: %ld binary128 verdicts, %ld undecided\n", maps, differing, quad, undecided);
  CHECK(differing == 0);
}
