#pragma once
// A prepared SQLite statement that finalizes itself and throws on every error, and exec for
// statements without parameters; shared by the run store and the review server's store. Errors
// read "<what>: <SQLite's message>", `what` naming the store.

#include <sqlite3.h>

#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace mtcs::store {

class Statement {
 public:
  Statement(sqlite3* db, const char* sql, const char* what = "run store") : db_(db), what_(what) {
    if (sqlite3_prepare_v2(db, sql, -1, &stmt_, nullptr) != SQLITE_OK)
      throw std::runtime_error(std::string(what_) + ": " + sqlite3_errmsg(db));
  }
  ~Statement() { sqlite3_finalize(stmt_); }
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  Statement& bind(int i, double v) { return check(sqlite3_bind_double(stmt_, i, v)); }
  Statement& bind(int i, long v) { return check(sqlite3_bind_int64(stmt_, i, v)); }
  Statement& bind(int i, int v) { return check(sqlite3_bind_int(stmt_, i, v)); }
  Statement& bind(int i, const std::string& v) {
    return check(sqlite3_bind_text(stmt_, i, v.c_str(), int(v.size()), SQLITE_TRANSIENT));
  }
  Statement& bind_null(int i) { return check(sqlite3_bind_null(stmt_, i)); }
  Statement& bind(int i, const std::vector<double>& v) {
    return check(sqlite3_bind_blob(stmt_, i, v.data(), int(v.size() * sizeof(double)), SQLITE_TRANSIENT));
  }
  bool step() {
    const int rc = sqlite3_step(stmt_);
    if (rc == SQLITE_ROW) return true;
    if (rc == SQLITE_DONE) return false;
    throw std::runtime_error(std::string(what_) + ": " + sqlite3_errmsg(db_));
  }
  void reset() { sqlite3_reset(stmt_); }
  bool null(int i) const { return sqlite3_column_type(stmt_, i) == SQLITE_NULL; }
  double real(int i) const { return sqlite3_column_double(stmt_, i); }
  long integer(int i) const { return long(sqlite3_column_int64(stmt_, i)); }
  std::string text(int i) const {
    const auto* p = sqlite3_column_text(stmt_, i);
    return p ? reinterpret_cast<const char*>(p) : "";
  }
  std::vector<double> doubles(int i) const {
    const void* blob = sqlite3_column_blob(stmt_, i);
    const auto bytes = std::size_t(sqlite3_column_bytes(stmt_, i));
    if (bytes % sizeof(double) != 0)
      throw std::runtime_error(std::string(what_) + ": a stored vector of " + std::to_string(bytes) +
                               " bytes, not whole doubles");
    std::vector<double> v(bytes / sizeof(double));
    if (bytes > 0) std::memcpy(v.data(), blob, bytes);
    return v;
  }

 private:
  Statement& check(int rc) {
    if (rc != SQLITE_OK) throw std::runtime_error(std::string(what_) + ": " + sqlite3_errmsg(db_));
    return *this;
  }
  sqlite3* db_;
  const char* what_;
  sqlite3_stmt* stmt_ = nullptr;
};

inline void exec(sqlite3* db, const char* sql, const char* what = "run store") {
  char* err = nullptr;
  if (sqlite3_exec(db, sql, nullptr, nullptr, &err) != SQLITE_OK) {
    const std::string msg = err ? err : "unknown error";
    sqlite3_free(err);
    throw std::runtime_error(std::string(what) + ": " + msg);
  }
}

}  // namespace mtcs::store
