// Fuzz target: the point CSV reader. Bad input must end in io::InputError, nothing else.
#include "fuzz_file.h"
#include "mtcs/io/input_error.h"
#include "mtcs/io/points_csv.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const mtcs::fuzz::InputFile file(data, size, "points.csv");
  try {
    (void)mtcs::io::read_points_csv(file.path());
  } catch (const mtcs::io::InputError&) {
  }
  return 0;
}
