// Fuzz target: the run-store loader: the input is a run.sqlite, opened as replay and resume
// open it and read through. A bad store must end in io::InputError, nothing else.
#include "fuzz_file.h"
#include "mtcs/io/input_error.h"
#include "mtcs/store/run_store.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const mtcs::fuzz::InputFile file(data, size, "run.sqlite");
  try {
    const auto store = mtcs::store::RunStore::open(file.path());
    (void)store.meta();
    (void)store.summaries();
    (void)store.last();
  } catch (const mtcs::io::InputError&) {
  }
  return 0;
}
