#pragma once
// mtcs bench hypervolume (experiments/hypervolume).

#include <cstddef>
#include <string>

namespace mtcs::bench {

// CSV on stdout; contributions only for fronts of at most max_contribution_n points.
int bench_hypervolume(const std::string& dir, int repeat, std::size_t max_contribution_n);

}  // namespace mtcs::bench
