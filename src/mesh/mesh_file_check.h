#pragma once
// Checks made before CGAL's readers see a mesh file: inputs on which those readers run into
// undefined behaviour (found by the libFuzzer targets of fuzz/, see experiments/fuzz/). Throws
// MeshError naming the file and line.

#include <string>

namespace mtcs::mesh {

void check_mesh_file(const std::string& path);

}  // namespace mtcs::mesh
