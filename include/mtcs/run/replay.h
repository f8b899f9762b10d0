#pragma once
// The files of `mtcs replay`: every stored generation re-evaluated (the check of --verify), and
// for a sample of them the feasible non-dominated front as CSV and JSON plus frames.json (the
// plots' index, the same axes throughout), and the last sampled front's layouts (YAML, bores CSV
// and STL). The folder appears whole or not at all: written beside DIR/replay under a temporary
// name and renamed over it at the end; an interrupted replay leaves the previous one intact.

#include <filesystem>
#include <functional>
#include <optional>

#include "mtcs/run/session.h"
#include "mtcs/store/run_store.h"

namespace mtcs::run {

struct ReplayChoice {
  std::optional<int> generation;  // only this stored generation
  int every = 0;                  // every N-th stored generation (the last always); 0: a sample
  bool all = false;               // every stored generation
};

// About this many generations when neither --every nor --all is given.
inline constexpr int kReplaySample = 50;

// The indices a choice keeps, from the stored ones (ascending). Throws io::InputError
// ("generation") for a --generation that was not stored.
std::vector<int> replayed_generations(const std::vector<int>& stored, const ReplayChoice& choice,
                                      const std::string& db_path);

struct ReplayResult {
  std::size_t generations = 0;  // replayed (files written)
  long checked = 0;             // individuals re-evaluated
  long mismatches = 0;          // whose objectives or violation differ from the stored ones
  std::filesystem::path folder; // DIR/replay
};

// Writes DIR/replay. `before_commit` may add files (the plots) to the folder while it is still
// under its temporary name.
ReplayResult write_replay(const Session& session, const store::RunStore& db, const std::string& dir,
                          const ReplayChoice& choice,
                          const std::function<void(const std::filesystem::path& folder)>& before_commit = {});

}  // namespace mtcs::run
