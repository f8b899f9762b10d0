// Fuzz target: the cylinder CSV reader. Bad input must end in io::InputError, nothing else.
#include "fuzz_file.h"
#include "mtcs/io/input_error.h"
#include "mtcs/io/cylinders_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const mtcs::fuzz::InputFile file(data, size, "cylinders.csv");
  try {
    (void)mtcs::io::read_cylinders_csv(file.path());
  } catch (const mtcs::io::InputError&) {
  }
  return 0;
}
