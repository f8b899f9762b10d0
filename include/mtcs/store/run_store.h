#pragma once
// The run store (SQLite): what a run was (the run record of run/run_record.h: resolved config,
// the mold spec's path, text and hash, its meshes' hashes, seed, program version) and every
// generation's population — genotype, strategy parameters, objectives, total violation, the
// violated constraints in words, feasibility — with a summary. One transaction per generation
// (or per batch of whole generations), so a run killed at any moment (kill -9 included) keeps
// every committed generation and resumes from the last. Commits reach the system's page cache,
// not the disk (WAL, synchronous=NORMAL): a power loss may lose the last commits, never the
// store's consistency. Numbers are stored as their exact bits: a resumed run continues bit for bit.
// A store that is not one (truncated, corrupted, another program's file) is bad input:
// io::InputError naming the file, and nothing is written to it. A writing store (create,
// resume) holds an advisory lock (flock on "<store>.lock") for its life, so a second writer is
// refused with "in use"; the kernel drops the lock when the process dies, kill -9 included.

#include <exception>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "mtcs/opt/population.h"

struct sqlite3;

namespace mtcs::store {

// One stored generation of an island run: every island's and the archipelago's (all members).
// merged.population[j] is member merged_from[j] of the islands' members in island order
// (empty: merged holds them in that order).
struct IslandsGeneration {
  std::vector<opt::Generation> islands;
  opt::Generation merged;
  double seconds = 0;
  std::vector<int> merged_from;
};

struct GenerationSummary {
  int index = 0;
  long evaluations = 0;
  double best = 0;           // best scalarised value
  double feasible_share = 0;  // of the population
  double seconds = 0;        // wall time since the run started
};

class RunStore {
 public:
  // Creates a new store (fails if the file exists or another process writes there) with the
  // run's metadata; meta must name the "program" ("mtcs ...").
  static RunStore create(const std::string& path, const std::map<std::string, std::string>& meta);
  // Opens an existing store to read it (replay, tests), read only, while a run may be writing.
  static RunStore open(const std::string& path);
  // Opens an existing store to continue writing it: refused while another process writes it.
  static RunStore resume(const std::string& path);
  // Whether a process writes the store at `path` now (holds its lock).
  static bool in_use(const std::string& path);

  RunStore(RunStore&&) noexcept;
  RunStore& operator=(RunStore&&) noexcept;
  ~RunStore();

  std::map<std::string, std::string> meta() const;
  // A generation saved within kCommitWindow of the last commit joins the open transaction; the
  // first one past it commits them all (a fast run does not pay a commit per generation: ~8 % of
  // an ES run on the gear mold, experiments/evaluate/es_run.md). commit() ends the transaction
  // at once: the run's end, a reader elsewhere. A failed save rolls back the uncommitted ones.
  static constexpr double kCommitWindow = 0.2;  // seconds
  void save(const opt::Generation& g, double seconds);
  void commit();
  std::optional<opt::Generation> last() const;
  std::optional<opt::Generation> generation(int index) const;
  std::vector<GenerationSummary> summaries() const;

  // Island runs (run/islands.h): one row per island member and generation in tables of their
  // own, made by the first save_islands (older stores keep their schema and open as before). One
  // transaction holds every island's generation and the archipelago's (`merged`: all islands'
  // members, which the readers of whole runs - replay, report, resume's checks - see as usual).
  // The archipelago's members are stored once, as their island rows with their rank in the
  // archipelago (island tables made before that keep a copy of them in the run's table).
  void save_islands(const std::vector<opt::Generation>& islands, const opt::Generation& merged, double seconds);
  // Several whole generations in one transaction (a writer that fell behind catches up): a
  // failure keeps none of them, the store ends at the last generation of an earlier one.
  void save_islands(const std::vector<IslandsGeneration>& batch);
  std::optional<opt::Generation> island_generation(int island, int index) const;
  // Summaries of one island's stored generations, in order (empty: none).
  std::vector<GenerationSummary> island_summaries(int island) const;

 private:
  RunStore(sqlite3* db, std::string path, int lock_fd);
  void insert_islands(const IslandsGeneration& gen);
  void commit_or_throw();
  [[noreturn]] void roll_back_and_throw(const std::exception& e);
  sqlite3* db_ = nullptr;
  std::string path_;
  int lock_fd_ = -1;  // the advisory lock of a writing store
  bool island_tables_ = false;  // made (by this connection's save_islands): no DDL per commit
  bool archipelago_by_reference_ = false;  // island rows carry archipelago_rank (new tables)
  bool in_transaction_ = false;  // save's generations since the last commit
  int first_uncommitted_ = 0, last_saved_ = 0;  // of that transaction
  double last_commit_ = -1e300;  // steady-clock seconds
  struct Prepared;  // the island inserts, prepared once a connection
  std::unique_ptr<Prepared> prepared_;
  struct RunRows;  // the run table's inserts (save), prepared once a connection
  std::unique_ptr<RunRows> run_rows_;
};

}  // namespace mtcs::store
