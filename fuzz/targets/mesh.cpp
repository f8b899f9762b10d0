// Fuzz target: one mesh reader, picked by the extension MTCS_MESH_EXTENSION (the build makes
// one binary per format). Bad input must end in mesh::MeshError, nothing else.
#include "fuzz_file.h"
#include "mtcs/mesh/mesh_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const mtcs::fuzz::InputFile file(data, size, "mesh." MTCS_MESH_EXTENSION);
  try {
    (void)mtcs::mesh::read_mesh(file.path());
  } catch (const mtcs::mesh::MeshError&) {
  }
  return 0;
}
