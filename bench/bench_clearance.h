#pragma once
// mtcs bench clearance (experiments/mesh).

#include <string>
#include <vector>

namespace mtcs::bench {

// For each mesh and its certified cases: BVH build time and cylinder-vs-mesh distance time and
// error, ours (exact, and with the upper bound bound_fraction x the mesh's largest extent) and
// FCL's, in the same run. CSV on stdout.
int bench_clearance(const std::vector<std::string>& meshes, const std::vector<std::string>& cases, int repeat,
                    int builds, double bound_fraction);

}  // namespace mtcs::bench
