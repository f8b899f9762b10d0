#include "mtcs/store/run_store.h"

#include <sqlite3.h>

#include <cstring>
#include <filesystem>
#include <stdexcept>

namespace mtcs::store {
namespace {

class Statement {
 public:
  Statement(sqlite3* db, const char* sql) : db_(db) {
    if (sqlite3_prepare_v2(db, sql, -1, &stmt_, nullptr) != SQLITE_OK)
      throw std::runtime_error(std::string("run store: ") + sqlite3_errmsg(db));
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement& bind(int i, double v) { return check(sqlite3_bind_double(stmt_, i, v)); }
  Statement& bind(int i, long v) { return check(sqlite3_bind_int64(stmt_, i, v)); }
  Statement& bind(int i, int v) { return check(sqlite3_bind_int(stmt_, i, v)); }
  Statement& bind(int i, const std::string& v) {
    return check(sqlite3_bind_text(stmt_, i, v.c_str(), int(v.size()), SQLITE_TRANSIENT));
  }
  Statement& bind(int i, const std::vector<double>& v) {
    return check(sqlite3_bind_blob(stmt_, i, v.data(), int(v.size() * sizeof(double)), SQLITE_TRANSIENT));
  }
  bool step() {
    const int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc == SQLITE_DONE) return false;
    throw std::runtime_error(std::string("run store: ") + sqlite3_errmsg(db_));
  }
  void reset() { sqlite3_reset(stmt_); }
  double real(int i) const { return sqlite3_column_double(stmt_, i); }
  long integer(int i) const { return long(sqlite3_column_int64(stmt_, i)); }
  std::string text(int i) const {
    const auto* p = sqlite3_column_text(stmt_, i);
    return p ? reinterpret_cast<const char*>(p) : "";
  }
  std::vector<double> doubles(int i) const {
    const int bytes = sqlite3_column_bytes(stmt_, i);
    std::vector<double> v(std::size_t(bytes) / sizeof(double));
    if (bytes > 0) std::memcpy(v.data(), sqlite3_column_blob(stmt_, i), std::size_t(bytes));
    return v;
  }

 private:
  Statement& check(int rc) {
    if (rc != SQLITE_OK) throw std::runtime_error(std::string("run store: ") + sqlite3_errmsg(db_));
    return *this;
  }
  sqlite3* db_;
  sqlite3_stmt* stmt_ = nullptr;
};

void exec(sqlite3* db, const char* sql) {
  char* err = nullptr;
  if (sqlite3_exec(db, sql, nullptr, nullptr, &err) != SQLITE_OK) {
    const std::string msg = err ? err : "unknown error";
    sqlite3_free(err);
    throw std::runtime_error("run store: " + msg);
  }
}

sqlite3* open_db(const std::string& path, int flags) {
  sqlite3* db = nullptr;
  if (sqlite3_open_v2(path.c_str(), &db, flags, nullptr) != SQLITE_OK) {
    const std::string msg = db ? sqlite3_errmsg(db) : "cannot open";
    sqlite3_close(db);
    throw std::runtime_error("run store " + path + ": " + msg);
  }
  exec(db, "PRAGMA journal_mode=WAL; PRAGMA synchronous=FULL;");
  return db;
}

}  // namespace

RunStore::RunStore(sqlite3* db) : db_(db) {}
RunStore::RunStore(RunStore&& o) noexcept : db_(o.db_) { o.db_ = nullptr; }
RunStore& RunStore::operator=(RunStore&& o) noexcept {
  std::swap(db_, o.db_);
  return *this;
}
RunStore::~RunStore() { sqlite3_close(db_); }

RunStore RunStore::create(const std::string& path, const std::map<std::string, std::string>& meta) {
  if (std::filesystem::exists(path)) throw std::runtime_error("run store " + path + " exists already");
  RunStore s(open_db(path, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE));
  exec(s.db_,
       "BEGIN;"
       "CREATE TABLE meta(key TEXT PRIMARY KEY, value TEXT NOT NULL);"
       "CREATE TABLE generation(idx INTEGER PRIMARY KEY, evaluations INTEGER, best REAL,"
       "  feasible_share REAL, seconds REAL);"
       "CREATE TABLE individual(generation INTEGER, rank INTEGER, genotype BLOB, steps BLOB,"
       "  objectives BLOB, violation REAL, feasible INTEGER, value REAL, violations TEXT,"
       "  PRIMARY KEY(generation, rank));"
       "COMMIT;");
  Statement ins(s.db_, "INSERT INTO meta(key, value) VALUES(?, ?)");
  for (const auto& [k, v] : meta) {
    ins.bind(1, k).bind(2, v).step();
    ins.reset();
  }
  return s;
}

RunStore RunStore::open(const std::string& path) {
  if (!std::filesystem::exists(path)) throw std::runtime_error("run store " + path + " not found");
  return RunStore(open_db(path, SQLITE_OPEN_READWRITE));
}

std::map<std::string, std::string> RunStore::meta() const {
  std::map<std::string, std::string> m;
  Statement q(db_, "SELECT key, value FROM meta");
  while (q.step()) m[q.text(0)] = q.text(1);
  return m;
}

void RunStore::save(const opt::Generation& g, double seconds) {
  exec(db_, "BEGIN IMMEDIATE;");
  try {
    int feasible = 0;
    Statement ins(db_,
                  "INSERT INTO individual(generation, rank, genotype, steps, objectives, violation, feasible, value,"
                  " violations) VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?)");
    for (std::size_t r = 0; r < g.population.size(); ++r) {
      const auto& ind = g.population[r];
      feasible += ind.score.feasible ? 1 : 0;
      ins.bind(1, g.index).bind(2, int(r)).bind(3, ind.x).bind(4, ind.steps).bind(5, ind.score.objectives);
      ins.bind(6, ind.score.violation).bind(7, ind.score.feasible ? 1 : 0).bind(8, ind.score.value);
      ins.bind(9, ind.score.detail).step();
      ins.reset();
    }
    Statement gen(db_, "INSERT INTO generation(idx, evaluations, best, feasible_share, seconds) VALUES(?, ?, ?, ?, ?)");
    gen.bind(1, g.index).bind(2, g.evaluations);
    gen.bind(3, g.population.empty() ? 0.0 : g.population.front().score.value);
    gen.bind(4, g.population.empty() ? 0.0 : double(feasible) / double(g.population.size())).bind(5, seconds).step();
    exec(db_, "COMMIT;");
  } catch (...) {
    exec(db_, "ROLLBACK;");
    throw;
  }
}

std::optional<opt::Generation> RunStore::generation(int index) const {
  Statement g(db_, "SELECT evaluations FROM generation WHERE idx = ?");
  g.bind(1, index);
  if (!g.step()) return std::nullopt;
  opt::Generation out;
  out.index = index;
  out.evaluations = g.integer(0);
  Statement q(db_,
              "SELECT genotype, steps, objectives, violation, feasible, value, violations FROM individual"
              " WHERE generation = ? ORDER BY rank");
  q.bind(1, index);
  while (q.step()) {
    opt::Individual ind;
    ind.x = q.doubles(0);
    ind.steps = q.doubles(1);
    ind.score = {q.doubles(2), q.real(3), q.integer(4) != 0, q.real(5), q.text(6)};
    out.population.push_back(std::move(ind));
  }
  return out;
}

std::optional<opt::Generation> RunStore::last() const {
  Statement m(db_, "SELECT idx FROM generation ORDER BY idx DESC LIMIT 1");
  if (!m.step()) return std::nullopt;
  return generation(int(m.integer(0)));
}

std::vector<GenerationSummary> RunStore::summaries() const {
  std::vector<GenerationSummary> out;
  Statement q(db_, "SELECT idx, evaluations, best, feasible_share, seconds FROM generation ORDER BY idx");
  while (q.step()) out.push_back({int(q.integer(0)), q.integer(1), q.real(2), q.real(3), q.real(4)});
  return out;
}

}  // namespace mtcs::store
