#pragma once
// Parts as CAD exchange files (STEP, IGES) tessellated into triangles; read_mesh calls this for
// .step/.stp/.iges/.igs. Built with OpenCASCADE where present (cad_reader.cpp, the only mesh
// file that includes it), else every call says how to get it (cad_reader_missing.cpp).

#include <string>

#include "mtcs/mesh/triangle_mesh.h"

namespace mtcs::mesh {

// Whether this build reads STEP and IGES.
bool cad_available();
// The solids of a STEP or IGES file in millimetres, each face tessellated to within
// kCadChordalTolerance of its surface (and kCadAngularTolerance between neighbouring normals),
// faces oriented as the solid's outside, coincident vertices of neighbouring faces merged.
// Throws MeshError naming the file.
TriangleMesh read_cad(const std::string& path);

}  // namespace mtcs::mesh
