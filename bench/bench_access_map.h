#pragma once
// Accessibility maps (mtcs bench access-map): AICA, ICA and the exact CheckBox on every case
// file of a folder in one run, each map compared cell by cell with CheckBox's. The timing
// helpers are shared with the hidden scaling runs of tests/voxel/access_map_timing.cpp.

#include <string>
#include <vector>

#include "mtcs/voxel/accessibility_map.h"

namespace mtcs::bench {

struct AccessMapBenchOptions {
  std::string cases;      // folder of case files (*.txt)
  std::string mesh_root;  // meshes resolved against it ("" : as the case files say)
  int threads = 1;        // 1: thread CPU time; more: wall time
  int repeat = 5;         // timed runs per map (best)
  int am_rows = 0, am_cols = 0;  // 0: the case's sphere grid
  bool json = false;
};

// One row per method (CSV) or one JSON object on stdout.
int bench_access_map(const AccessMapBenchOptions& options);

// Milliseconds of one map, best of `reps` runs: CPU time of the calling thread on one thread
// (a one-slot arena runs the map on the caller, and a loaded machine does not count), wall time
// otherwise. The last map is kept in `out` when given.
double time_access_map(const voxel::Octree& tree, const voxel::Vec3& pivot, const voxel::Tool& tool,
                       const voxel::SphereGrid& sphere, const voxel::AmOptions& options, voxel::AccessMap* out, int reps);

// Linear-interpolated quantile q in [0, 1] of a non-empty sample.
double quantile(std::vector<double> v, double q);

// Cells where two maps of the same sphere grid differ.
long differing_cells(const voxel::AccessMap& a, const voxel::AccessMap& b);

}  // namespace mtcs::bench
