#pragma once
// `mtcs replay`: re-evaluates the populations a mold run stored and writes, in out_dir, each
// replayed generation's feasible non-dominated front (front_G.csv, front_G.json), frames.json
// (the series for plot_fronts.py: per-objective limits over every stored front, so the axes of
// an animation hold still) and the last replayed front's layouts (front_G_rankR.layout.yaml,
// .bores.csv, .bores.stl).

#include <optional>
#include <string>

#include "mtcs/run/session.h"
#include "mtcs/store/run_store.h"

namespace mtcs::run {

struct Replay {
  long generations = 0;  // replayed (0: no such stored generation; nothing written)
  long checked = 0;      // individuals re-evaluated
  long mismatches = 0;   // whose objectives or violation differ from the stored ones (bit for bit)
};

// `generation`: only that stored generation (default: all).
Replay replay_fronts(const store::RunStore& db, const Session& session, std::optional<int> generation,
                     const std::string& out_dir);

}  // namespace mtcs::run
