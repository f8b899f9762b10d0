#include "mtcs/store/run_store.h"

#include <fcntl.h>
#include <sqlite3.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "mtcs/io/crash_point.h"
#include "mtcs/io/input_error.h"
#include "mtcs/store/sqlite_statement.h"

namespace mtcs::store {
namespace {

sqlite3* open_db(const std::string& path, int flags) {
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(path.c_str(), &db, flags, nullptr) != SQLITE_OK) {
    const std::string msg = db ? sqlite3_errmsg(db) : "cannot open";
    sqlite3_close(db);
    throw io::InputError(path, 0, 0, "", "cannot open the run store: " + msg);
  }
  sqlite3_busy_timeout(db, 10000);  // a reader may meet a writer's checkpoint
  return db;
}

// A writing store: write-ahead log, synced at checkpoints only (synchronous=NORMAL). A commit
// is in the system's page cache when it returns, so a process killed at any moment (kill -9
// included) loses nothing committed; only a power loss or a system crash can lose the last
// commits, and the log's checksums keep the store whole even then (it resumes from its last
// whole generation). A commit synced to the disk (FULL) costs 0.3-10 ms here, more than an
// island generation's evaluations (experiments/islands/README.md).
constexpr const char* kWriting = "PRAGMA journal_mode=WAL; PRAGMA synchronous=NORMAL;";

// A writer killed inside a rollback-journal transaction leaves a hot journal beside the store
// (its end is one: it takes the store out of WAL mode). A read-only connection cannot roll it
// back (SQLITE_READONLY_ROLLBACK, "attempt to write a readonly database"); a read-write one does
// on its first read, as SQLite recovers any killed writer. Only then, and only for a file that
// is an SQLite database: anything else is left as it is, for the check to refuse.
void roll_back_killed_writer(const std::string& path) {
  std::error_code none;
  if (!std::filesystem::exists(path + "-journal", none)) return;
  {
    char header[16] = {};
    std::ifstream in(path, std::ios::binary);
    if (!in.read(header, sizeof header) || std::memcmp(header, "SQLite format 3", sizeof header) != 0) return;
  }
  sqlite3* db = nullptr;
  bool hot = false;
  if (sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr) == SQLITE_OK)
    hot = sqlite3_exec(db, "SELECT count(*) FROM sqlite_master", nullptr, nullptr, nullptr) != SQLITE_OK &&
          sqlite3_extended_errcode(db) == SQLITE_READONLY_ROLLBACK;
  sqlite3_close(db);
  if (!hot) return;
  db = nullptr;
  if (sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr) == SQLITE_OK) {
    sqlite3_busy_timeout(db, 10000);  // another reader rolling it back at the same moment
    sqlite3_exec(db, "SELECT count(*) FROM sqlite_master", nullptr, nullptr, nullptr);
  }
  sqlite3_close(db);  // errors are the check's to report, on the read-only connection
}

[[noreturn]] void bad_store(const std::string& path, const std::string& what) {
  throw io::InputError(path, 0, 0, "", what + "; the file is left as it is");
}

// Refuses a file that is not a whole run store of mtcs, reading only: SQLite's quick check
// (truncated or overwritten pages), the tables and columns the store reads, the program.
// Every SQLite error on the way (a page that only a later query meets) is bad input too.
void check_store(sqlite3* db, const std::string& path) {
  try {
    Statement check(db, "PRAGMA quick_check");
    check.step();
    if (check.text(0) != "ok") bad_store(path, "the run store is corrupted (" + check.text(0) + ")");
    try {
      Statement(db, "SELECT key, value FROM meta LIMIT 0");
      Statement(db, "SELECT idx, evaluations, best, feasible_share, seconds FROM generation LIMIT 0");
      Statement(db,
                "SELECT generation, rank, genotype, steps, objectives, violation, feasible, value, violations"
                " FROM individual LIMIT 0");
    } catch (const std::runtime_error& e) {
      bad_store(path, "not a run store of mtcs (" + std::string(e.what()) + ")");
    }
    Statement program(db, "SELECT value FROM meta WHERE key = 'program'");
    if (!program.step() || program.text(0).rfind("mtcs", 0) != 0)
      bad_store(path, "not a run store of mtcs (no 'program' entry naming mtcs in its meta table)");
  } catch (const io::InputError&) {
    throw;
  } catch (const std::runtime_error& e) {
    bad_store(path, "not a readable run store (" + std::string(e.what()) + ")");
  }
}

// The advisory lock of a writing store: an open descriptor of "<store>.lock" with flock held.
// The writer removes the file when it ends (no stray file in a finished run's folder), still
// holding the lock; so a lock taken on a file no longer at the path is the ended writer's, and
// the lock is taken again on a fresh file.
int lock_store(const std::string& path) {
  const std::string lock_path = path + ".lock";
  for (;;) {
    const int fd = ::open(lock_path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd < 0) throw std::runtime_error("run store " + path + ": cannot open its lock file " + lock_path);
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      ::close(fd);
      throw io::InputError(path, 0, 0, "",
                           "the run is in use: another process writes this run store (stop it, or wait for it to end)");
    }
    struct stat held, named;
    if (::fstat(fd, &held) == 0 && ::stat(lock_path.c_str(), &named) == 0 && held.st_dev == named.st_dev &&
        held.st_ino == named.st_ino)
      return fd;
    ::close(fd);
  }
}

void unlock_store(const std::string& path, int fd) {
  ::unlink((path + ".lock").c_str());  // while held: see lock_store
  ::close(fd);                         // closing drops the flock
}

bool has_table(sqlite3* db, const char* table) {
  Statement q(db, "SELECT count(*) FROM sqlite_master WHERE type = 'table' AND name = ?");
  q.bind(1, std::string(table));
  q.step();
  return q.integer(0) > 0;
}

bool has_column(sqlite3* db, const char* table, const char* column) {
  Statement q(db, "SELECT count(*) FROM pragma_table_info(?) WHERE name = ?");
  q.bind(1, std::string(table)).bind(2, std::string(column));
  q.step();
  return q.integer(0) > 0;
}

// Stores made before 2026-11-25 have no `stalled` column (the ES's generations since its best
// improved, which its restart reads): added, 0 for the generations they hold.
void add_stalled_columns(sqlite3* db) {
  for (const char* table : {"generation", "island_generation"}) {
    if (has_table(db, table) && !has_column(db, table, "stalled"))
      exec(db, (std::string("ALTER TABLE ") + table + " ADD COLUMN stalled INTEGER NOT NULL DEFAULT 0;").c_str());
  }
}

// The public reads turn SQLite's errors (a page corrupted after the open's check) into bad input.
template <class F>
auto reading(const std::string& path, F&& read) {
  try {
    return read();
  } catch (const io::InputError&) {
    throw;
  } catch (const std::runtime_error& e) {
    bad_store(path, std::string("cannot read the run store: ") + e.what());
  }
}

// A generation's stall count (the ES's restart reads it): at most its index.
int stalled_count(long stored, int index) {
  if (stored < 0 || stored > index)
    throw std::runtime_error("generation " + std::to_string(index) + " has a stall count of " + std::to_string(stored) +
                             ", not 0.." + std::to_string(index));
  return int(stored);
}

}  // namespace

constexpr const char* kInsertGeneration =
    "INSERT INTO generation(idx, evaluations, best, feasible_share, seconds, stalled) VALUES(?, ?, ?, ?, ?, ?)";

// The statements of save_islands, prepared once a connection (preparing them per commit cost
// the writer thread a few percent of an island run's CPU).
struct RunStore::Prepared {
  Prepared(sqlite3* db, bool by_reference)
      : island_row(db, by_reference ? "INSERT INTO island_individual(island, generation, rank, genotype, steps, objectives,"
                                      " violation, feasible, value, violations, archipelago_rank)"
                                      " VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)"
                                    : "INSERT INTO island_individual(island, generation, rank, genotype, steps, objectives,"
                                      " violation, feasible, value, violations) VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?)"),
        island_generation(db,
                          "INSERT INTO island_generation(island, idx, evaluations, best, feasible_share, seconds,"
                          " stalled) VALUES(?, ?, ?, ?, ?, ?, ?)"),
        generation(db, kInsertGeneration) {}
  Statement island_row, island_generation, generation;
};

RunStore::RunStore(sqlite3* db, std::string path, int lock_fd) : db_(db), path_(std::move(path)), lock_fd_(lock_fd) {}
RunStore::RunStore(RunStore&& o) noexcept
    : db_(o.db_), path_(std::move(o.path_)), lock_fd_(o.lock_fd_), island_tables_(o.island_tables_),
      archipelago_by_reference_(o.archipelago_by_reference_), in_transaction_(o.in_transaction_),
      first_uncommitted_(o.first_uncommitted_), last_saved_(o.last_saved_), last_commit_(o.last_commit_),
      prepared_(std::move(o.prepared_)), run_rows_(std::move(o.run_rows_)) {
  o.db_ = nullptr;
  o.in_transaction_ = false;
  o.lock_fd_ = -1;
}
RunStore& RunStore::operator=(RunStore&& o) noexcept {
  std::swap(db_, o.db_);
  std::swap(path_, o.path_);
  std::swap(lock_fd_, o.lock_fd_);
  std::swap(island_tables_, o.island_tables_);
  std::swap(archipelago_by_reference_, o.archipelago_by_reference_);
  std::swap(in_transaction_, o.in_transaction_);
  std::swap(first_uncommitted_, o.first_uncommitted_);
  std::swap(last_saved_, o.last_saved_);
  std::swap(last_commit_, o.last_commit_);
  std::swap(prepared_, o.prepared_);
  std::swap(run_rows_, o.run_rows_);
  return *this;
}
RunStore::~RunStore() {
  // Whole generations only are ever in the open transaction: they are kept.
  if (db_ && in_transaction_) sqlite3_exec(db_, "COMMIT;", nullptr, nullptr, nullptr);
  prepared_.reset();  // finalized before the close
  run_rows_.reset();
  // A writer ending leaves the store out of WAL mode (the log checkpointed into it), so that a
  // reader of the finished run (report, replay, export: read-only) creates no -wal and -shm
  // beside it that it could not remove. A reader still attached keeps it in WAL mode: no wait.
  if (db_ && lock_fd_ >= 0) {
    sqlite3_busy_timeout(db_, 0);
    sqlite3_exec(db_, "PRAGMA journal_mode=DELETE;", nullptr, nullptr, nullptr);
  }
  sqlite3_close(db_);
  if (lock_fd_ >= 0) unlock_store(path_, lock_fd_);
}

bool RunStore::in_use(const std::string& path) {
  const int fd = ::open((path + ".lock").c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool held = ::flock(fd, LOCK_SH | LOCK_NB) != 0;
  ::close(fd);
  return held;
}

RunStore RunStore::create(const std::string& path, const std::map<std::string, std::string>& meta) {
  const int lock = lock_store(path);
  std::error_code unreadable;
  if (std::filesystem::exists(path, unreadable)) {
    unlock_store(path, lock);
    throw io::InputError(path, 0, 0, "", "a run store exists here already");
  }
  RunStore s(nullptr, path, lock);
  // Built whole beside the store, then renamed into place: a run killed while creating it
  // leaves no store or a whole one (tables and program), never a file that is no run store.
  const std::string fresh = path + ".new";
  for (const char* suffix : {"", "-journal", "-wal", "-shm"}) std::filesystem::remove(fresh + suffix);
  {
    sqlite3* db = open_db(fresh, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE);
    const std::unique_ptr<sqlite3, int (*)(sqlite3*)> closing(db, sqlite3_close);
    exec(db, "PRAGMA synchronous=FULL;");  // the new file reaches the disk before its rename
    exec(db,
         "BEGIN;"
         "CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT NOT NULL);"
         "CREATE TABLE generation(idx INTEGER PRIMARY KEY, evaluations INTEGER, best REAL,"
         "  feasible_share REAL, seconds REAL, stalled INTEGER NOT NULL DEFAULT 0);"
         "CREATE TABLE individual(generation INTEGER, rank INTEGER, genotype BLOB, steps BLOB,"
         "  objectives BLOB, violation REAL, feasible INTEGER, value REAL, violations TEXT,"
         "  PRIMARY KEY(generation, rank));");
    {
      Statement ins(db, "INSERT INTO meta(key, value) VALUES(?, ?)");
      for (const auto& [k, v] : meta) {
        ins.bind(1, k).bind(2, v).step();
        ins.reset();
      }
    }
    exec(db, "COMMIT;");
    exec(db, "PRAGMA journal_mode=WAL;");  // kept in the file's header
  }
  io::crash_point("store-create");
  std::filesystem::rename(fresh, path);
  s.db_ = open_db(path, SQLITE_OPEN_READWRITE);
  exec(s.db_, kWriting);
  return s;
}

RunStore RunStore::open(const std::string& path) {
  std::error_code unreadable;
  if (!std::filesystem::is_regular_file(path, unreadable)) throw io::InputError(path, 0, 0, "", "no run store here");
  roll_back_killed_writer(path);
  RunStore s(open_db(path, SQLITE_OPEN_READONLY), path, -1);
  check_store(s.db_, path);
  return s;
}

RunStore RunStore::resume(const std::string& path) {
  std::error_code unreadable;
  if (!std::filesystem::is_regular_file(path, unreadable)) throw io::InputError(path, 0, 0, "", "no run store here");
  const int lock = lock_store(path);
  RunStore s(nullptr, path, lock);
  // Checked through a read-only connection first: nothing is written to a file that is no store.
  check_store(RunStore::open(path).db_, path);
  s.db_ = open_db(path, SQLITE_OPEN_READWRITE);
  exec(s.db_, kWriting);
  add_stalled_columns(s.db_);
  return s;
}

std::map<std::string, std::string> RunStore::meta() const {
  return reading(path_, [&] {
    std::map<std::string, std::string> m;
    Statement q(db_, "SELECT key, value FROM meta");
    while (q.step()) m[q.text(0)] = q.text(1);
    return m;
  });
}

namespace {

// A generation's summary row in the run's table (`gen`: its prepared insert).
void insert_summary(Statement& gen, const opt::Generation& g, double seconds) {
  long feasible = 0;
  for (const auto& ind : g.population) feasible += ind.score.feasible ? 1 : 0;
  gen.reset();
  gen.bind(1, g.index).bind(2, g.evaluations);
  gen.bind(3, g.population.empty() ? 0.0 : g.population.front().score.value);
  gen.bind(4, g.population.empty() ? 0.0 : double(feasible) / double(g.population.size())).bind(5, seconds);
  gen.bind(6, g.stalled).step();
}

constexpr const char* kInsertMember =
    "INSERT INTO individual(generation, rank, genotype, steps, objectives, violation, feasible, value,"
    " violations) VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?)";

// One generation's members in the run's table (inside the caller's transaction; `ins`: its
// prepared insert).
void insert_members(Statement& ins, const opt::Generation& g) {
  ins.reset();
  for (std::size_t r = 0; r < g.population.size(); ++r) {
    const auto& ind = g.population[r];
    ins.bind(1, g.index).bind(2, int(r)).bind(3, ind.x).bind(4, ind.steps).bind(5, ind.score.objectives);
    ins.bind(6, ind.score.violation).bind(7, ind.score.feasible ? 1 : 0).bind(8, ind.score.value);
    ins.bind(9, ind.score.detail).step();
    ins.reset();
    io::crash_point("store-row");
  }
}

}  // namespace

// The run table's inserts, prepared once a connection: an ES step on a fast mold takes ~1 ms,
// and preparing both per generation cost the run ~2 % of its CPU (experiments/evaluate/es_run.md).
struct RunStore::RunRows {
  explicit RunRows(sqlite3* db) : member(db, kInsertMember), generation(db, kInsertGeneration) {}
  Statement member, generation;
};

namespace {

double steady_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

void RunStore::save(const opt::Generation& g, double seconds) {
  errno = 0;
  try {
    if (!in_transaction_) exec(db_, "BEGIN IMMEDIATE;"), in_transaction_ = true, first_uncommitted_ = g.index;
    last_saved_ = g.index;
    if (!run_rows_) run_rows_ = std::make_unique<RunRows>(db_);
    insert_members(run_rows_->member, g);
    insert_summary(run_rows_->generation, g, seconds);
    if (steady_seconds() - last_commit_ >= kCommitWindow) commit_or_throw();
  } catch (const std::exception& e) {
    roll_back_and_throw(e);
  }
}

void RunStore::commit() {
  errno = 0;
  try {
    commit_or_throw();
  } catch (const std::exception& e) {
    roll_back_and_throw(e);
  }
}

void RunStore::commit_or_throw() {
  if (!in_transaction_) return;
  exec(db_, "COMMIT;");
  in_transaction_ = false;
  last_commit_ = steady_seconds();
}

void RunStore::roll_back_and_throw(const std::exception& e) {
  // The system's word for a failed write (no space left, file too large) says what to do;
  // SQLite keeps it only for some errors, errno still has it.
  const int os_error = errno;
  const bool disk = os_error == ENOSPC || os_error == EFBIG || os_error == EDQUOT || os_error == EIO || os_error == EROFS;
  sqlite3_exec(db_, "ROLLBACK;", nullptr, nullptr, nullptr);  // keeps the last committed generation
  in_transaction_ = false;
  const std::string what = "cannot save generation " + std::to_string(last_saved_) +
                           (first_uncommitted_ < last_saved_
                                ? " (nor " + std::to_string(first_uncommitted_) + " to " + std::to_string(last_saved_ - 1) +
                                      ", saved since the last commit)"
                                : "");
  throw std::runtime_error(path_ + ": " + what + ": " + e.what() +
                           (disk ? " (" + std::string(std::strerror(os_error)) + ")" : ""));
}

namespace {

bool has_island_tables(sqlite3* db) { return has_table(db, "island_generation"); }

// Whether the island rows carry the archipelago's ranks (island tables made since 2026-11-25),
// and the run's table no copy of the archipelago's members.
bool has_archipelago_rank(sqlite3* db) { return has_column(db, "island_individual", "archipelago_rank"); }

}  // namespace

namespace {

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

// Each island member's rank in the archipelago's generation (island order), checked against
// `merged`: the store keeps the archipelago as these references, so they must be right.
std::vector<int> archipelago_ranks(const IslandsGeneration& gen) {
  std::vector<const opt::Individual*> all;
  for (const auto& g : gen.islands)
    for (const auto& ind : g.population) all.push_back(&ind);
  const auto n = all.size();
  const auto& merged = gen.merged.population;
  if (merged.size() != n || (!gen.merged_from.empty() && gen.merged_from.size() != n))
    throw std::invalid_argument("run store: the archipelago's generation " + std::to_string(gen.merged.index) +
                                " is not its islands' members");
  std::vector<int> rank(n, -1);
  for (std::size_t j = 0; j < n; ++j) {
    const auto from = gen.merged_from.empty() ? j : std::size_t(gen.merged_from[j]);
    if (from >= n || rank[from] >= 0 || !same_bits(all[from]->x, merged[j].x) ||
        !same_bits({all[from]->score.value}, {merged[j].score.value}))
      throw std::invalid_argument("run store: member " + std::to_string(j) + " of the archipelago's generation " +
                                  std::to_string(gen.merged.index) + " is not the island member it names");
    rank[from] = int(j);
  }
  return rank;
}

}  // namespace

// One generation of every island and the archipelago's (inside the caller's transaction).
void RunStore::insert_islands(const IslandsGeneration& gen) {
  Prepared& p = *prepared_;
  const std::vector<int> archipelago_rank = archipelago_ranks(gen);
  std::size_t member = 0;
  for (std::size_t i = 0; i < gen.islands.size(); ++i) {
    const opt::Generation& g = gen.islands[i];
    int feasible = 0;
    for (std::size_t r = 0; r < g.population.size(); ++r, ++member) {
      const auto& ind = g.population[r];
      feasible += ind.score.feasible ? 1 : 0;
      Statement& ins = p.island_row;
      ins.reset();
      ins.bind(1, int(i)).bind(2, g.index).bind(3, int(r)).bind(4, ind.x).bind(5, ind.steps);
      ins.bind(6, ind.score.objectives).bind(7, ind.score.violation).bind(8, ind.score.feasible ? 1 : 0);
      ins.bind(9, ind.score.value).bind(10, ind.score.detail);
      if (archipelago_by_reference_) ins.bind(11, archipelago_rank[member]);
      ins.step();
      io::crash_point("store-island-row");
    }
    Statement& row = p.island_generation;
    row.reset();
    row.bind(1, int(i)).bind(2, g.index).bind(3, g.evaluations);
    row.bind(4, g.population.empty() ? 0.0 : g.population.front().score.value);
    row.bind(5, g.population.empty() ? 0.0 : double(feasible) / double(g.population.size())).bind(6, gen.seconds);
    row.bind(7, g.stalled).step();
  }
  if (!archipelago_by_reference_) {
    Statement ins(db_, kInsertMember);
    insert_members(ins, gen.merged);
  }
  insert_summary(p.generation, gen.merged, gen.seconds);
}

void RunStore::save_islands(const std::vector<opt::Generation>& islands, const opt::Generation& merged, double seconds) {
  save_islands({IslandsGeneration{islands, merged, seconds, {}}});
}

void RunStore::save_islands(const std::vector<IslandsGeneration>& batch) {
  if (batch.empty()) return;
  commit();  // save's generations first: one transaction at a time
  errno = 0;
  try {
    exec(db_, "BEGIN IMMEDIATE;");
    if (!island_tables_) {
      // New tables keep the archipelago as references (archipelago_rank), in generation order
      // (appended, one b-tree); tables of an older store keep their schema and its copies.
      exec(db_,
           "CREATE TABLE IF NOT EXISTS island_generation(island INTEGER, idx INTEGER, evaluations INTEGER, best REAL,"
           "  feasible_share REAL, seconds REAL, stalled INTEGER NOT NULL DEFAULT 0, PRIMARY KEY(island, idx));"
           "CREATE TABLE IF NOT EXISTS island_individual(island INTEGER, generation INTEGER, rank INTEGER, genotype BLOB,"
           "  steps BLOB, objectives BLOB, violation REAL, feasible INTEGER, value REAL, violations TEXT,"
           "  archipelago_rank INTEGER, PRIMARY KEY(generation, island, rank)) WITHOUT ROWID;");
      archipelago_by_reference_ = has_archipelago_rank(db_);
      prepared_ = std::make_unique<Prepared>(db_, archipelago_by_reference_);
    }
    for (const IslandsGeneration& gen : batch) insert_islands(gen);
    exec(db_, "COMMIT;");
    island_tables_ = true;
  } catch (const std::exception& e) {
    const int os_error = errno;
    const bool disk = os_error == ENOSPC || os_error == EFBIG || os_error == EDQUOT || os_error == EIO || os_error == EROFS;
    sqlite3_exec(db_, "ROLLBACK;", nullptr, nullptr, nullptr);  // keeps the last whole generation
    const int first = batch.front().merged.index, last = batch.back().merged.index;
    throw std::runtime_error(path_ + ": cannot save the islands' generation" +
                             (first == last ? " " + std::to_string(first)
                                            : "s " + std::to_string(first) + " to " + std::to_string(last)) +
                             ": " + e.what() + (disk ? " (" + std::string(std::strerror(os_error)) + ")" : ""));
  }
}
namespace {

// The members a query of (genotype, steps, objectives, violation, feasible, value, violations)
// returns, in its order, into `out`.
void read_members(Statement& q, opt::Generation& out) {
  while (q.step()) {
    opt::Individual ind;
    ind.x = q.doubles(0);
    ind.steps = q.doubles(1);
    ind.score = {q.doubles(2), q.real(3), q.integer(4) != 0, q.real(5), q.text(6)};
    out.population.push_back(std::move(ind));
  }
}

}  // namespace


std::optional<opt::Generation> RunStore::island_generation(int island, int index) const {
  return reading(path_, [&]() -> std::optional<opt::Generation> {
    if (!has_island_tables(db_)) return std::nullopt;
    Statement g(db_, has_column(db_, "island_generation", "stalled")
                         ? "SELECT evaluations, stalled FROM island_generation WHERE island = ? AND idx = ?"
                         : "SELECT evaluations, 0 FROM island_generation WHERE island = ? AND idx = ?");
    g.bind(1, island).bind(2, index);
    if (!g.step()) return std::nullopt;
    opt::Generation out;
    out.index = index;
    out.evaluations = g.integer(0);
    out.stalled = stalled_count(g.integer(1), index);
    Statement q(db_,
                "SELECT genotype, steps, objectives, violation, feasible, value, violations FROM island_individual"
                " WHERE island = ? AND generation = ? ORDER BY rank");
    q.bind(1, island).bind(2, index);
    read_members(q, out);
    return out;
  });
}

std::vector<GenerationSummary> RunStore::island_summaries(int island) const {
  return reading(path_, [&] {
    std::vector<GenerationSummary> out;
    if (!has_island_tables(db_)) return out;
    Statement q(db_,
                "SELECT idx, evaluations, best, feasible_share, seconds FROM island_generation WHERE island = ?"
                " ORDER BY idx");
    q.bind(1, island);
    while (q.step()) out.push_back({int(q.integer(0)), q.integer(1), q.real(2), q.real(3), q.real(4)});
    return out;
  });
}

std::optional<opt::Generation> RunStore::generation(int index) const {
  return reading(path_, [&]() -> std::optional<opt::Generation> {
    Statement g(db_, has_column(db_, "generation", "stalled") ? "SELECT evaluations, stalled FROM generation WHERE idx = ?"
                                                               : "SELECT evaluations, 0 FROM generation WHERE idx = ?");
    g.bind(1, index);
    if (!g.step()) return std::nullopt;
    opt::Generation out;
    out.index = index;
    out.evaluations = g.integer(0);
    out.stalled = stalled_count(g.integer(1), index);
    Statement q(db_,
                "SELECT genotype, steps, objectives, violation, feasible, value, violations FROM individual"
                " WHERE generation = ? ORDER BY rank");
    q.bind(1, index);
    read_members(q, out);
    if (out.population.empty() && has_island_tables(db_) && has_archipelago_rank(db_)) {
      // An island run's archipelago: its members are the island rows, in their archipelago rank.
      Statement a(db_,
                  "SELECT genotype, steps, objectives, violation, feasible, value, violations FROM island_individual"
                  " WHERE generation = ? ORDER BY archipelago_rank");
      a.bind(1, index);
      read_members(a, out);
    }
    return out;
  });
}

std::optional<opt::Generation> RunStore::last() const {
  const std::optional<long> index = reading(path_, [&]() -> std::optional<long> {
    Statement m(db_, "SELECT idx FROM generation ORDER BY idx DESC LIMIT 1");
    if (!m.step()) return std::nullopt;
    return m.integer(0);
  });
  if (!index) return std::nullopt;
  return generation(int(*index));
}

std::vector<GenerationSummary> RunStore::summaries() const {
  return reading(path_, [&] {
    std::vector<GenerationSummary> out;
    Statement q(db_, "SELECT idx, evaluations, best, feasible_share, seconds FROM generation ORDER BY idx");
    while (q.step()) out.push_back({int(q.integer(0)), q.integer(1), q.real(2), q.real(3), q.real(4)});
    return out;
  });
}

}  // namespace mtcs::store
