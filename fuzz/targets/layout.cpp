// Fuzz target: the layout YAML reader, against the bundled plate mold (its drilling diameters
// decide which circuits are valid). Bad input must end in io::InputError, nothing else.
#include "fuzz_file.h"
#include "mtcs/io/input_error.h"
#include "mtcs/mold/layout_io.h"
#include "mtcs/mold/mold_spec.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const mtcs::mold::MoldSpec spec = mtcs::mold::load_mold_spec(MTCS_SOURCE_DIR "/molds/plate.yaml");
  const mtcs::fuzz::InputFile file(data, size, "layout.yaml");
  try {
    (void)mtcs::mold::load_layout(file.path(), spec);
  } catch (const mtcs::io::InputError&) {
  }
  return 0;
}
