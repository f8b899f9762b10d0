#pragma once
// Checks made before CGAL's readers see a mesh file: inputs on which those readers run into
// undefined behaviour (found by the libFuzzer targets of fuzz/, see experiments/fuzz/). Throws
// MeshError naming the file and line.

#include <string>

namespace mtcs::mesh {

// A vertex's coordinates are finite and at most this large (mm: a million km), as
// io::kMaxCoordinate bounds the mold spec's: NaN, infinities and 1e308 are refused by the reader.
inline constexpr double kMaxMeshCoordinate = 1e9;

void check_mesh_file(const std::string& path);

}  // namespace mtcs::mesh
