// Fuzz target: the mold-spec YAML reader (with the meshes it names, relative to the spec's
// folder: meshes/ there links to fuzz/mold_spec_meshes/, stand-ins of the bundled molds' meshes
// with the same names and bounds, the big ones as boxes: the gear's 11 416 triangles made every
// execution that reached its self-intersection check cost ~1 s, 200 executions/s on average,
// while the mesh readers have targets of their own). Bad input must end in io::InputError,
// nothing else.
#include "fuzz_file.h"
#include "mtcs/io/input_error.h"
#include "mtcs/mold/mold_spec.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool linked = [] {
    std::filesystem::create_directory_symlink(MTCS_SOURCE_DIR "/fuzz/mold_spec_meshes", mtcs::fuzz::scratch_folder() / "meshes");
    return true;
  }();
  (void)linked;
  const mtcs::fuzz::InputFile file(data, size, "mold.yaml");
  try {
    (void)mtcs::mold::load_mold_spec(file.path());
  } catch (const mtcs::io::InputError&) {
  }
  return 0;
}
