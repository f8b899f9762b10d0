// Fuzz target: the front file reader (hv_fronts format). Bad input must end in io::InputError, nothing else.
#include "fuzz_file.h"
#include "mtcs/io/input_error.h"
#include "mtcs/io/front_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const mtcs::fuzz::InputFile file(data, size, "front.txt");
  try {
    (void)mtcs::io::read_front(file.path());
  } catch (const mtcs::io::InputError&) {
  }
  return 0;
}
