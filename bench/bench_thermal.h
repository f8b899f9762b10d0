#pragma once
// Error against run time of the thermal tiers (mtcs bench thermal): every tier and setting on
// the same random layouts, judged against the finite-volume reference at a fine cell.

#include <cstdint>
#include <string>
#include <vector>

namespace mtcs::bench {

struct ThermalBenchOptions {
  std::string scene = "block";  // "block" (shared/cases/thermal's block) or a MOLD.yaml
  int layouts = 60;
  double reference_cell = 1.0;  // mm, T3's cell for the reference
  std::uint64_t seed = 20261124;
  int repeat = 5;               // timed solves per layout (median)
  bool json = false;
  std::vector<double> void_panels{6, 10};
  int circuits = 3;            // per random layout of a mold (4 legs each)
  bool through_part = false;
  bool difference = false;     // a mold: the points across the part too (tau of temperature_difference)
  std::vector<std::string> tiers;  // labels' starts ("t2d M=4", "fd"); empty: every tier
  std::vector<int> sample_images;  // also every line-sink tier with this many image levels summed
                                   // exactly at the samples (LineSinkOptions::sample_images)
};

// Prints one row per tier: CSV on stdout, or a JSON object with default_tier and tiers.
int bench_thermal(const ThermalBenchOptions& options);

}  // namespace mtcs::bench
