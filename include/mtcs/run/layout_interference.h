#pragma once
// `mtcs interfere MOLD.yaml --layout LAYOUT.yaml`: the bores of a layout against the part, every
// keep-out and each other, through the evaluation pipeline's exact kernels.

#include <ostream>
#include <string>
#include <vector>

#include "mtcs/eval/evaluation.h"
#include "mtcs/eval/pipeline.h"
#include "mtcs/mold/genome.h"

namespace mtcs::run {

struct LayoutInterference {
  std::size_t bores = 0;
  std::vector<std::string> against;      // "cavity" (when the mold has one), then each keep-out
  std::vector<eval::Violation> found;    // bore_cavity, bore_keepout and bore_bore violations
  long crossing = 0;                     // of them, bores that touch, cross or lie inside the other
  double nearest = 0;                    // smallest distance found (inf: none)
};

// Every bore that crosses or comes closer than its clearance to the cavity, a keep-out or
// another bore, with the distance and the place.
LayoutInterference layout_interference(const eval::Pipeline& pipeline, const mold::Genome& genome);

// As `mtcs interfere MOLD --layout` prints it: one JSON object {mold, layout, bores, against, pairs,
// distance, violations[{kind, bore, against, interferes, distance, clearance, where}]}, or a table.
void write_layout_interference_json(std::ostream& os, const LayoutInterference& r, const std::string& mold_path,
                                    const std::string& layout_path);
void write_layout_interference_text(std::ostream& os, const LayoutInterference& r);

}  // namespace mtcs::run
