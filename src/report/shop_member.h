#pragma once
// A stored member as the shop receives it: the genome rounded and tidied by run::shop_layout (as
// optimize writes best.layout.yaml and replay the front layouts), re-scored as written, and its
// hole table (run::shop_plan: what bores.csv, bores.stl and the exports give).

#include <string>

#include "mtcs/mold/genome.h"
#include "mtcs/mold/layout.h"
#include "mtcs/opt/population.h"
#include "mtcs/run/session.h"

namespace mtcs::report {

struct ShopMember {
  mold::Genome genome;  // best.layout.yaml's layout
  mold::Layout layout;  // decoded (what the pipeline and the thermal model score)
  mold::Layout plan;    // hole ends rounded to the tolerance (bores.csv)
  opt::Score score;     // as optimize re-scores the written layout
};

ShopMember shop_member(const run::Session& session, const opt::Genotype& x);

// What the run store cannot show: `optimize --polish` refines the best after the last generation
// and writes that to best.layout.yaml without storing it. A sentence saying so when RUN_DIR's
// summary.json records a polish that improved the best; empty otherwise.
std::string polish_note(const std::string& run_dir);

}  // namespace mtcs::report
