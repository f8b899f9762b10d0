#pragma once
// `mtcs interfere MOLD.yaml --layout LAYOUT.yaml`: the bores of a layout against the part, every
// keep-out and each other, through the evaluation pipeline's exact kernels.

#include <string>

namespace mtcs::cli {

// Prints every bore that crosses or comes closer than its clearance to the cavity, a keep-out
// or another bore, with the distance and the place; `json` prints one object instead.
int run_layout_interference(const std::string& mold_path, const std::string& layout_path, bool json);

}  // namespace mtcs::cli
