#pragma once
// mtcs bench interfere (experiments/mesh/interference.md).

#include <string>

namespace mtcs::bench {

// CSV on stdout, one row per placement of the cases file (mesh_interference.csv format).
int bench_interfere(const std::string& cases, const std::string& meshes, int repeat);

}  // namespace mtcs::bench
