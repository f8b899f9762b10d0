#pragma once
// One run of mtcs compare-penalties: the optimiser on the session's mold with one penalty
// variant (the config's) and one seed, with the feasible share of the evaluated layouts per
// tenth of the budget and the hypervolume of the final feasible front.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "mtcs/run/session.h"

namespace mtcs::run {

constexpr int kDeciles = 10;

// The evaluations of one tenth of the budget (for the ES rounded up to whole generations).
struct Window {
  long from = 0, to = 0, evaluated = 0, feasible = 0;
};

struct PenaltyRun {
  std::string variant;
  std::uint64_t seed = 0;
  long evaluations = 0, feasible = 0;
  double hypervolume = 0, seconds = 0;
  std::size_t front_size = 0;
  std::vector<Window> windows;
};

// `config` is the session's with the variant to compare (config.penalty); the hypervolume is in
// scaled objectives against scaled_ref. The feasible share is counted at the first generation at
// or past each tenth of the budget (one evaluation for SMS-EMOA); on_decile sees each tenth close.
PenaltyRun run_with_penalty(const Session& session, RunConfig config, std::uint64_t seed,
                            const std::vector<double>& scaled_ref, const std::function<void(int)>& on_decile);

}  // namespace mtcs::run
