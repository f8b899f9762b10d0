// Hidden timing runs (not part of the suite); the timing over all public cases is
// `mtcs bench access-map --cases tests/data/access_maps --mesh-root tests/data/meshes`
// (bench/bench_access_map.cpp, whose timing helpers these runs share).

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <random>

#include "bench/bench_access_map.h"
#include "mtcs/voxel/accessibility_map.h"
#include "voxel/case_files.h"
#include "support/paths.h"

using namespace mtcs;
using namespace mtcs::voxel;

namespace {

double wall_ms() { return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

double time_map(const Octree& tree, const AccessCase& c, const SphereGrid& sphere, const AmOptions& o, AccessMap* out, int reps) {
  return bench::time_access_map(tree, c.pivot, c.tool, sphere, o, out, reps);
}

}  // namespace

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
