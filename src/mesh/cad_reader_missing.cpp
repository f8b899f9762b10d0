// STEP and IGES without OpenCASCADE: a clear error naming the file and how to get the component.
#include "cad_reader.h"

#include "mtcs/mesh/mesh_io.h"

namespace mtcs::mesh {

bool cad_available() { return false; }

TriangleMesh read_cad(const std::string& path) {
  throw MeshError(path + ": STEP and IGES are read through the optional OpenCASCADE component: install it "
                         "(bash scripts/setup.sh) and build with -DMTCS_WITH_OCCT=ON, or export the part as STL");
}

}  // namespace mtcs::mesh
