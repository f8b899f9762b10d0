#pragma once
// What a mold run stores about its mold and config (the run store's metadata), so that a replay
// needs neither the mold where it was nor unchanged: the spec's path, text and hash, the hash of
// every mesh it loads, the resolved config, the objectives. And the check of a mold on disk
// against that record.

#include <map>
#include <string>
#include <vector>

#include "mtcs/mold/mold_spec.h"
#include "mtcs/opt/problem.h"

namespace mtcs::run {

class Session;
using RunMeta = std::map<std::string, std::string>;

// FNV-1a, 64 bits, as 16 hex digits: identifies a file's bytes.
std::string content_hash(const std::string& bytes);
// The file's bytes; io::InputError when it cannot be read.
std::string read_file_text(const std::string& path);

// The record of a new run on the session's mold, read from `mold_path`.
RunMeta mold_run_meta(const std::string& mold_path, const Session& session);

// A run's --start layouts (meta "start"), as the genotypes its initial population began with:
// one line of numbers each, written to round-trip exactly (a resume, a replay and a report
// rebuild the same initial population and reference point without the layout files).
std::string start_text(const std::vector<opt::Genotype>& start);
// None when the run had none; io::InputError naming `origin` and the line for a damaged record.
std::vector<opt::Genotype> stored_start(const RunMeta& meta, const std::string& origin);

// The mold at `mold_path` against the run's record.
struct MoldCheck {
  bool spec_changed = false;
  std::vector<std::string> meshes_changed;  // by their path relative to the spec's folder
  bool same() const { return !spec_changed && meshes_changed.empty(); }
  std::string describe() const;             // "the spec text and mesh part.stl differ", ...
};
MoldCheck check_mold(const RunMeta& meta, const std::string& mold_path, const mold::MoldSpec& loaded);

// The mold spec a stored run is replayed against, and what to tell the user about it:
//  - `override_path` (the mold moved) when given, checked against the run's record;
//  - else the spec at its stored path, checked (an edited mold is named with what changed);
//  - else, the file gone, the spec text stored in the run, when the spec loads no mesh files.
// io::InputError when none can be loaded (a mold with meshes that is gone: give its new path).
mold::MoldSpec stored_mold_spec(const RunMeta& meta, const std::string& override_path, std::string* note);

}  // namespace mtcs::run
