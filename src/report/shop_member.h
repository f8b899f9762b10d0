#pragma once
// A stored member as the shop receives it: the genome rounded and tidied by run::shop_layout (as
// optimize writes best.layout.yaml and replay the front layouts), re-scored as written, and its
// hole table (run::shop_plan: what bores.csv, bores.stl and the exports give).

#include <optional>
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
// and writes it to best.layout.yaml without storing it. That layout, as the shop receives it, when
// RUN_DIR's summary.json records a polish that improved the best and best.layout.yaml still scores
// the summary's best_objective (not edited since); `note` then says so. None otherwise, and where
// the file no longer matches, `note` says the stored best stands in for it.
// The session must score objectives (eval::PipelineScope::everything): the file is checked by its score.
std::optional<ShopMember> polished_best(const std::string& run_dir, const run::Session& session, std::string& note);
// Does RUN_DIR's summary.json record a polish that improved the best (so that polished_best may apply)?
bool was_polished(const std::string& run_dir);

}  // namespace mtcs::report
