// Fuzz target: the BCF 3.0 reader of `mtcs serve` (an uploaded .bcf file's bytes, read in memory).
// Bad input must end in serve::BcfError, nothing else.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "mtcs/serve/bcf_import.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    (void)mtcs::serve::read_bcf(std::string_view(reinterpret_cast<const char*>(data), size));
  } catch (const mtcs::serve::BcfError&) {
  }
  return 0;
}
