#pragma once
// The STEP writer of `mtcs export --format step`: step_writer.cpp with OpenCASCADE (the only
// file that includes it), step_writer_missing.cpp without it (CMake picks one: MTCS_WITH_OCCT).

#include <string>

#include "mtcs/mold/layout.h"

namespace mtcs::report {

inline constexpr const char* kStepMissing =
    "step: this mtcs was built without OpenCASCADE; install it (Debian: apt-get install libocct-data-exchange-dev "
    "libocct-modeling-algorithms-dev libocct-modeling-data-dev libocct-ocaf-dev libocct-foundation-dev, or "
    "bash scripts/setup.sh) and rebuild (bash scripts/build.sh: CMake finds it; -DMTCS_WITH_OCCT=ON insists); "
    "or export vtp, obj or csv";

// AP214, mm: one solid per bore, named as in the bores CSV.
void write_step(const std::string& path, const mold::Layout& layout);

}  // namespace mtcs::report
