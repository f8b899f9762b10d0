#pragma once
// mtcs bench distance, tolerance and stiff (experiments/distance). CSV on stdout.

#include <string>
#include <vector>

namespace mtcs::bench {

// Every named variant of the kernel (full, bounded-U5, no-pretests, no-sorted-bounds, naive,
// fcl, segment-floor) per category of the pairs.
int bench_distance(const std::string& pairs_csv, const std::vector<std::string>& variants, int repeat, double tolerance);
// The full kernel at each tolerance.
int bench_tolerance(const std::string& pairs_csv, const std::vector<double>& tolerances, int repeat);
// The full kernel's worst errors by pair sub-type.
int bench_stiff(const std::string& pairs_csv, int repeat, double tolerance);

}  // namespace mtcs::bench
