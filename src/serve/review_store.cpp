#include "mtcs/serve/review_store.h"

#include <sqlite3.h>

#include <cctype>
#include <chrono>
#include <map>
#include <set>
#include <stdexcept>

#include "mtcs/serve/bcf_export.h"
#include "mtcs/store/sqlite_statement.h"

namespace mtcs::serve {
namespace {

using nlohmann::json;
constexpr const char* kWhat = "review store";

struct Query : store::Statement {
  Query(sqlite3* db, const char* sql) : store::Statement(db, sql, kWhat) {}
};

double now() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

// Numbered migrations: a store written by an older mtcs is brought up to date at open.
const char* const kMigrations[] = {
    "CREATE TABLE user(id INTEGER PRIMARY KEY, name TEXT UNIQUE NOT NULL, password TEXT NOT NULL,"
    "  role TEXT NOT NULL, created REAL NOT NULL);"
    "CREATE TABLE session(digest TEXT PRIMARY KEY, user INTEGER NOT NULL REFERENCES user(id),"
    "  csrf TEXT NOT NULL, created REAL NOT NULL, seen REAL NOT NULL);"
    "CREATE TABLE token(digest TEXT PRIMARY KEY, user INTEGER NOT NULL REFERENCES user(id),"
    "  name TEXT NOT NULL, created REAL NOT NULL, used REAL);"
    "CREATE TABLE project(id INTEGER PRIMARY KEY, name TEXT UNIQUE NOT NULL, created_by INTEGER NOT NULL,"
    "  created REAL NOT NULL);"
    "CREATE TABLE member(project INTEGER NOT NULL REFERENCES project(id), user INTEGER NOT NULL REFERENCES user(id),"
    "  role TEXT NOT NULL, PRIMARY KEY(project, user));"
    "CREATE TABLE version(id INTEGER PRIMARY KEY, project INTEGER NOT NULL REFERENCES project(id),"
    "  component TEXT NOT NULL, seq INTEGER NOT NULL, kind TEXT NOT NULL, blob TEXT NOT NULL,"
    "  filename TEXT NOT NULL, size INTEGER NOT NULL, created_by INTEGER NOT NULL, created REAL NOT NULL,"
    "  UNIQUE(project, component, seq));"
    "CREATE TABLE job(id INTEGER PRIMARY KEY, project INTEGER NOT NULL REFERENCES project(id),"
    "  kind TEXT NOT NULL, inputs TEXT NOT NULL, scope TEXT NOT NULL, state TEXT NOT NULL,"
    "  message TEXT NOT NULL DEFAULT '', result TEXT, created_by INTEGER NOT NULL, created REAL NOT NULL,"
    "  finished REAL);"
    "CREATE TABLE finding(job INTEGER NOT NULL REFERENCES job(id), key TEXT NOT NULL, state TEXT NOT NULL,"
    "  payload TEXT NOT NULL, PRIMARY KEY(job, key));"
    "CREATE TABLE topic(id INTEGER PRIMARY KEY, project INTEGER NOT NULL REFERENCES project(id),"
    "  title TEXT NOT NULL, status TEXT NOT NULL, assignee TEXT NOT NULL DEFAULT '',"
    "  finding TEXT NOT NULL DEFAULT '', created_by INTEGER NOT NULL, created REAL NOT NULL,"
    "  modified REAL NOT NULL);"
    "CREATE TABLE comment(id INTEGER PRIMARY KEY, topic INTEGER NOT NULL REFERENCES topic(id),"
    "  text TEXT NOT NULL, viewpoint TEXT, author INTEGER NOT NULL, created REAL NOT NULL);"
    "CREATE TABLE event(id INTEGER PRIMARY KEY AUTOINCREMENT, project INTEGER NOT NULL, time REAL NOT NULL,"
    "  actor INTEGER NOT NULL, type TEXT NOT NULL, data TEXT NOT NULL);"
    "CREATE INDEX event_project ON event(project, id);",
    // 2: items from BCF files keep their GUIDs, descriptions, labels, due dates and the names of
    // authors who hold no account here.
    "ALTER TABLE topic ADD COLUMN guid TEXT NOT NULL DEFAULT '';"
    "ALTER TABLE topic ADD COLUMN description TEXT NOT NULL DEFAULT '';"
    "ALTER TABLE topic ADD COLUMN labels TEXT NOT NULL DEFAULT '[]';"
    "ALTER TABLE topic ADD COLUMN due REAL NOT NULL DEFAULT 0;"
    "ALTER TABLE topic ADD COLUMN author_name TEXT NOT NULL DEFAULT '';"
    "ALTER TABLE comment ADD COLUMN guid TEXT NOT NULL DEFAULT '';"
    "ALTER TABLE comment ADD COLUMN author_name TEXT NOT NULL DEFAULT '';"
    "CREATE INDEX topic_guid ON topic(project, guid);",
};

std::string name_of(sqlite3* db, long user) {
  Query q(db, "SELECT name FROM user WHERE id = ?");
  q.bind(1, user);
  return q.step() ? q.text(0) : "mtcs";  // 0: mtcs itself (a re-check's note)
}

json parse_or_null(const std::string& text) { return text.empty() ? json(nullptr) : json::parse(text); }

}  // namespace

ReviewStore::ReviewStore(const std::filesystem::path& file) {
  if (sqlite3_open_v2(file.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE | SQLITE_OPEN_FULLMUTEX,
                      nullptr) != SQLITE_OK) {
    const std::string msg = db_ ? sqlite3_errmsg(db_) : "cannot open";
    sqlite3_close(db_);
    throw std::runtime_error("cannot open the review store " + file.string() + ": " + msg);
  }
  sqlite3_busy_timeout(db_, 5000);
  store::exec(db_, "PRAGMA journal_mode=WAL; PRAGMA synchronous=NORMAL; PRAGMA foreign_keys=ON;", kWhat);
  store::exec(db_, "CREATE TABLE IF NOT EXISTS schema_version(v INTEGER NOT NULL);", kWhat);
  long version = 0;
  {
    Query q(db_, "SELECT coalesce(max(v), 0) FROM schema_version");
    if (q.step()) version = q.integer(0);
  }
  const long known = long(std::size(kMigrations));
  if (version > known)
    throw std::runtime_error("the review store " + file.string() + " was written by a newer mtcs (schema " +
                             std::to_string(version) + ", this one knows " + std::to_string(known) + ")");
  for (long v = version; v < known; ++v) {
    store::exec(db_, "BEGIN IMMEDIATE;", kWhat);
    try {
      store::exec(db_, kMigrations[v], kWhat);
      Query q(db_, "INSERT INTO schema_version(v) VALUES(?)");
      q.bind(1, v + 1).step();
      store::exec(db_, "COMMIT;", kWhat);
    } catch (...) {
      store::exec(db_, "ROLLBACK;", kWhat);
      throw;
    }
  }
}

ReviewStore::~ReviewStore() { sqlite3_close(db_); }

long ReviewStore::add_user(const std::string& name, const std::string& password_hash, Role role) {
  std::lock_guard lock(mutex_);
  {
    Query q(db_, "SELECT 1 FROM user WHERE name = ?");
    if (q.bind(1, name).step()) throw std::invalid_argument("a user named '" + name + "' exists already");
  }
  Query q(db_, "INSERT INTO user(name, password, role, created) VALUES(?, ?, ?, ?)");
  q.bind(1, name).bind(2, password_hash).bind(3, to_string(role)).bind(4, now()).step();
  return long(sqlite3_last_insert_rowid(db_));
}

std::optional<User> ReviewStore::user(const std::string& name, std::string* password_hash) {
  std::lock_guard lock(mutex_);
  Query q(db_, "SELECT id, role, password FROM user WHERE name = ?");
  if (!q.bind(1, name).step()) return std::nullopt;
  if (password_hash) *password_hash = q.text(2);
  return User{q.integer(0), name, role_from(q.text(1)).value_or(Role::viewer)};
}

long ReviewStore::user_count() {
  std::lock_guard lock(mutex_);
  Query q(db_, "SELECT count(*) FROM user");
  return q.step() ? q.integer(0) : 0;
}

void ReviewStore::add_session(const std::string& digest, long user, const std::string& csrf) {
  std::lock_guard lock(mutex_);
  Query q(db_, "INSERT INTO session(digest, user, csrf, created, seen) VALUES(?, ?, ?, ?, ?)");
  const double t = now();
  q.bind(1, digest).bind(2, user).bind(3, csrf).bind(4, t).bind(5, t).step();
}

std::optional<Session> ReviewStore::session(const std::string& digest, double max_idle_seconds, double max_age_seconds) {
  std::lock_guard lock(mutex_);
  Query q(db_,
          "SELECT user.id, user.name, user.role, session.csrf, session.seen, session.created FROM session JOIN user"
          " ON user.id = session.user WHERE session.digest = ?");
  if (!q.bind(1, digest).step()) return std::nullopt;
  const double t = now();
  if (t - q.real(4) > max_idle_seconds || t - q.real(5) > max_age_seconds) return std::nullopt;
  Session s{User{q.integer(0), q.text(1), role_from(q.text(2)).value_or(Role::viewer)}, q.text(3)};
  Query touch(db_, "UPDATE session SET seen = ? WHERE digest = ?");
  touch.bind(1, t).bind(2, digest).step();
  return s;
}

void ReviewStore::drop_session(const std::string& digest) {
  std::lock_guard lock(mutex_);
  Query q(db_, "DELETE FROM session WHERE digest = ?");
  q.bind(1, digest).step();
}

void ReviewStore::add_token(const std::string& digest, long user, const std::string& name) {
  std::lock_guard lock(mutex_);
  Query q(db_, "INSERT INTO token(digest, user, name, created) VALUES(?, ?, ?, ?)");
  q.bind(1, digest).bind(2, user).bind(3, name).bind(4, now()).step();
}

std::optional<User> ReviewStore::token_user(const std::string& digest) {
  std::lock_guard lock(mutex_);
  Query q(db_, "SELECT user.id, user.name, user.role FROM token JOIN user ON user.id = token.user WHERE digest = ?");
  if (!q.bind(1, digest).step()) return std::nullopt;
  return User{q.integer(0), q.text(1), role_from(q.text(2)).value_or(Role::viewer)};
}

long ReviewStore::add_project(const std::string& name, long owner) {
  std::lock_guard lock(mutex_);
  {
    Query q(db_, "SELECT 1 FROM project WHERE name = ?");
    if (q.bind(1, name).step()) throw std::invalid_argument("a project named '" + name + "' exists already");
  }
  store::exec(db_, "BEGIN IMMEDIATE;", kWhat);
  try {
    Query p(db_, "INSERT INTO project(name, created_by, created) VALUES(?, ?, ?)");
    p.bind(1, name).bind(2, owner).bind(3, now()).step();
    const long id = long(sqlite3_last_insert_rowid(db_));
    Query m(db_, "INSERT INTO member(project, user, role) VALUES(?, ?, 'owner')");
    m.bind(1, id).bind(2, owner).step();
    store::exec(db_, "COMMIT;", kWhat);
    return id;
  } catch (...) {
    store::exec(db_, "ROLLBACK;", kWhat);
    throw;
  }
}

std::optional<Role> ReviewStore::role_on(long project, const User& user) {
  std::lock_guard lock(mutex_);
  {
    Query q(db_, "SELECT 1 FROM project WHERE id = ?");
    if (!q.bind(1, project).step()) return std::nullopt;
  }
  if (user.role == Role::owner) return Role::owner;
  Query q(db_, "SELECT role FROM member WHERE project = ? AND user = ?");
  if (!q.bind(1, project).bind(2, user.id).step()) return std::nullopt;
  return role_from(q.text(0));
}

json ReviewStore::projects_of(const User& user) {
  std::lock_guard lock(mutex_);
  json out = json::array();
  Query q(db_,
          "SELECT p.id, p.name, coalesce(m.role, 'owner') FROM project p LEFT JOIN member m"
          " ON m.project = p.id AND m.user = ? WHERE m.user IS NOT NULL OR ? ORDER BY p.id");
  q.bind(1, user.id).bind(2, int(user.role == Role::owner));
  while (q.step()) {
    const std::string role = user.role == Role::owner ? "owner" : q.text(2);
    out.push_back({{"id", q.integer(0)}, {"name", q.text(1)}, {"role", role}});
  }
  return out;
}

json ReviewStore::project(long project) {
  std::lock_guard lock(mutex_);
  Query q(db_, "SELECT name, created FROM project WHERE id = ?");
  if (!q.bind(1, project).step()) return nullptr;
  json out{{"id", project}, {"name", q.text(0)}, {"created", q.real(1)}, {"members", json::array()}};
  Query m(db_, "SELECT user.name, member.role FROM member JOIN user ON user.id = member.user WHERE project = ? ORDER BY user.name");
  m.bind(1, project);
  while (m.step()) out["members"].push_back({{"user", m.text(0)}, {"role", m.text(1)}});
  return out;
}

void ReviewStore::set_member(long project, long user, Role role) {
  std::lock_guard lock(mutex_);
  Query q(db_, "INSERT INTO member(project, user, role) VALUES(?, ?, ?) ON CONFLICT(project, user) DO UPDATE SET role = excluded.role");
  q.bind(1, project).bind(2, user).bind(3, to_string(role)).step();
}

namespace {
Version version_row(Query& q) {
  Version v;
  v.id = q.integer(0), v.project = q.integer(1), v.component = q.text(2), v.seq = q.integer(3);
  v.kind = q.text(4), v.blob = q.text(5), v.filename = q.text(6), v.size = q.integer(7);
  return v;
}
constexpr const char* kVersionColumns = "SELECT id, project, component, seq, kind, blob, filename, size FROM version ";
}  // namespace

Version ReviewStore::add_version(long project, const std::string& component, const std::string& kind,
                                 const std::string& blob, const std::string& filename, long size, long user,
                                 bool* existed) {
  std::lock_guard lock(mutex_);
  store::exec(db_, "BEGIN IMMEDIATE;", kWhat);
  try {
    const std::string latest_sql = std::string(kVersionColumns) + "WHERE project = ? AND component = ? ORDER BY seq DESC LIMIT 1";
    Query last(db_, latest_sql.c_str());
    last.bind(1, project).bind(2, component);
    long seq = 1;
    if (last.step()) {
      Version v = version_row(last);
      if (v.blob == blob && v.kind == kind) {
        store::exec(db_, "COMMIT;", kWhat);
        if (existed) *existed = true;
        return v;
      }
      seq = v.seq + 1;
    }
    Query q(db_,
            "INSERT INTO version(project, component, seq, kind, blob, filename, size, created_by, created)"
            " VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?)");
    q.bind(1, project).bind(2, component).bind(3, seq).bind(4, kind).bind(5, blob).bind(6, filename);
    q.bind(7, size).bind(8, user).bind(9, now()).step();
    Version v{long(sqlite3_last_insert_rowid(db_)), project, seq, size, component, kind, blob, filename};
    store::exec(db_, "COMMIT;", kWhat);
    if (existed) *existed = false;
    return v;
  } catch (...) {
    store::exec(db_, "ROLLBACK;", kWhat);
    throw;
  }
}

std::optional<Version> ReviewStore::version(long project, long id) {
  std::lock_guard lock(mutex_);
  const std::string sql = std::string(kVersionColumns) + "WHERE project = ? AND id = ?";
  Query q(db_, sql.c_str());
  if (!q.bind(1, project).bind(2, id).step()) return std::nullopt;
  return version_row(q);
}

std::optional<Version> ReviewStore::latest(long project, const std::string& component) {
  std::lock_guard lock(mutex_);
  const std::string sql = std::string(kVersionColumns) + "WHERE project = ? AND component = ? ORDER BY seq DESC LIMIT 1";
  Query q(db_, sql.c_str());
  if (!q.bind(1, project).bind(2, component).step()) return std::nullopt;
  return version_row(q);
}

json ReviewStore::components(long project) {
  std::lock_guard lock(mutex_);
  json out = json::array();
  const std::string sql = std::string(kVersionColumns) + "WHERE project = ? ORDER BY component, seq";
  Query q(db_, sql.c_str());
  q.bind(1, project);
  while (q.step()) {
    const Version v = version_row(q);
    if (out.empty() || out.back()["name"] != v.component)
      out.push_back({{"name", v.component}, {"kind", v.kind}, {"versions", json::array()}});
    out.back()["versions"].push_back(
        {{"id", v.id}, {"seq", v.seq}, {"blob", v.blob}, {"filename", v.filename}, {"size", v.size}, {"kind", v.kind}});
  }
  return out;
}

long ReviewStore::add_job(long project, const std::string& kind, const json& inputs, const std::string& scope, long user) {
  std::lock_guard lock(mutex_);
  Query q(db_, "INSERT INTO job(project, kind, inputs, scope, state, created_by, created) VALUES(?, ?, ?, ?, 'queued', ?, ?)");
  q.bind(1, project).bind(2, kind).bind(3, inputs.dump()).bind(4, scope).bind(5, user).bind(6, now()).step();
  return long(sqlite3_last_insert_rowid(db_));
}

namespace {
constexpr const char* kJobColumns = "SELECT id, project, kind, state, scope, inputs FROM job ";
Job job_row(Query& q) { return Job{q.integer(0), q.integer(1), q.text(2), q.text(3), q.text(4), json::parse(q.text(5))}; }
}  // namespace

std::optional<Job> ReviewStore::job(long project, long id) {
  std::lock_guard lock(mutex_);
  const std::string sql = std::string(kJobColumns) + "WHERE project = ? AND id = ?";
  Query q(db_, sql.c_str());
  if (!q.bind(1, project).bind(2, id).step()) return std::nullopt;
  return job_row(q);
}

std::optional<Job> ReviewStore::claim_next() {
  std::lock_guard lock(mutex_);
  const std::string sql = std::string(kJobColumns) + "WHERE state = 'queued' ORDER BY id LIMIT 1";
  Query q(db_, sql.c_str());
  if (!q.step()) return std::nullopt;
  Job job = job_row(q);
  Query run(db_, "UPDATE job SET state = 'running' WHERE id = ?");
  run.bind(1, job.id).step();
  job.state = "running";
  return job;
}

namespace {
json job_json_row(sqlite3* db, Query& q) {
  return {{"id", q.integer(0)},      {"kind", q.text(1)},    {"state", q.text(2)},
          {"message", q.text(3)},    {"inputs", json::parse(q.text(4))},
          {"result", parse_or_null(q.text(5))}, {"created", q.real(6)}, {"finished", q.null(7) ? json(nullptr) : json(q.real(7))},
          {"created_by", name_of(db, q.integer(8))}};
}
constexpr const char* kJobJsonColumns = "SELECT id, kind, state, message, inputs, result, created, finished, created_by FROM job ";
}  // namespace

json ReviewStore::job_json(long project, long id) {
  std::lock_guard lock(mutex_);
  const std::string sql = std::string(kJobJsonColumns) + "WHERE project = ? AND id = ?";
  Query q(db_, sql.c_str());
  if (!q.bind(1, project).bind(2, id).step()) return nullptr;
  return job_json_row(db_, q);
}

json ReviewStore::jobs(long project) {
  std::lock_guard lock(mutex_);
  json out = json::array();
  const std::string sql = std::string(kJobJsonColumns) + "WHERE project = ? ORDER BY id";
  Query q(db_, sql.c_str());
  q.bind(1, project);
  while (q.step()) out.push_back(job_json_row(db_, q));
  return out;
}

long ReviewStore::queued_jobs(long project) {
  std::lock_guard lock(mutex_);
  Query q(db_, "SELECT count(*) FROM job WHERE project = ? AND state = 'queued'");
  return q.bind(1, project).step() ? q.integer(0) : 0;
}

void ReviewStore::set_job_state(long id, const std::string& state, const std::string& message, const json& result) {
  std::lock_guard lock(mutex_);
  const bool done = state != "queued" && state != "running";
  Query q(db_, "UPDATE job SET state = ?, message = ?, result = ?, finished = ? WHERE id = ?");
  q.bind(1, state).bind(2, message);
  if (result.is_null()) q.bind_null(3);
  else q.bind(3, result.dump());
  if (done) q.bind(4, now());
  else q.bind_null(4);
  q.bind(5, id).step();
}

bool ReviewStore::cancel_queued(long project, long id) {
  std::lock_guard lock(mutex_);
  Query q(db_, "UPDATE job SET state = 'cancelled', message = 'cancelled before it ran', finished = ? WHERE project = ? AND id = ? AND state = 'queued'");
  q.bind(1, now()).bind(2, project).bind(3, id).step();
  return sqlite3_changes(db_) == 1;
}

std::vector<Job> ReviewStore::interrupt_running() {
  std::lock_guard lock(mutex_);
  std::vector<Job> jobs;
  const std::string sql = std::string(kJobColumns) + "WHERE state = 'running'";
  Query q(db_, sql.c_str());
  while (q.step()) jobs.push_back(job_row(q));
  Query u(db_, "UPDATE job SET state = 'interrupted', message = 'the server stopped while it ran', finished = ? WHERE state = 'running'");
  u.bind(1, now()).step();
  return jobs;
}

std::vector<Finding> ReviewStore::settle_findings(const Job& job, std::vector<Finding> found) {
  std::lock_guard lock(mutex_);
  // The last succeeded job of the same scope before this one, and its open findings.
  std::map<std::string, json> before;
  {
    Query last(db_, "SELECT max(id) FROM job WHERE project = ? AND scope = ? AND state = 'succeeded' AND id < ?");
    last.bind(1, job.project).bind(2, job.scope).bind(3, job.id);
    if (last.step() && !last.null(0)) {
      Query f(db_, "SELECT key, payload FROM finding WHERE job = ? AND state != 'resolved'");
      f.bind(1, last.integer(0));
      while (f.step()) before[f.text(0)] = json::parse(f.text(1));
    }
  }
  for (Finding& f : found) {
    f.state = before.erase(f.key) ? "persistent" : "new";
  }
  for (auto& [key, payload] : before) found.push_back({key, "resolved", payload});
  store::exec(db_, "BEGIN IMMEDIATE;", kWhat);
  try {
    Query ins(db_, "INSERT OR REPLACE INTO finding(job, key, state, payload) VALUES(?, ?, ?, ?)");
    for (const Finding& f : found) {
      ins.reset();
      ins.bind(1, job.id).bind(2, f.key).bind(3, f.state).bind(4, f.payload.dump()).step();
    }
    store::exec(db_, "COMMIT;", kWhat);
  } catch (...) {
    store::exec(db_, "ROLLBACK;", kWhat);
    throw;
  }
  return found;
}

json ReviewStore::findings(long project, long job) {
  std::lock_guard lock(mutex_);
  json out = json::array();
  Query q(db_, "SELECT f.key, f.state, f.payload FROM finding f JOIN job j ON j.id = f.job WHERE j.project = ? AND f.job = ? ORDER BY f.rowid");
  q.bind(1, project).bind(2, job);
  while (q.step()) out.push_back({{"key", q.text(0)}, {"state", q.text(1)}, {"payload", json::parse(q.text(2))}});
  return out;
}

long ReviewStore::add_topic(long project, const std::string& title, const std::string& finding_key, long user) {
  std::lock_guard lock(mutex_);
  Query q(db_, "INSERT INTO topic(project, title, status, finding, created_by, created, modified) VALUES(?, ?, 'open', ?, ?, ?, ?)");
  const double t = now();
  q.bind(1, project).bind(2, title).bind(3, finding_key).bind(4, user).bind(5, t).bind(6, t).step();
  return long(sqlite3_last_insert_rowid(db_));
}

bool ReviewStore::update_topic(long project, long topic, const json& changes) {
  std::lock_guard lock(mutex_);
  Query exists(db_, "SELECT 1 FROM topic WHERE project = ? AND id = ?");
  if (!exists.bind(1, project).bind(2, topic).step()) return false;
  for (const char* field : {"title", "status", "assignee"}) {
    if (!changes.contains(field)) continue;
    const std::string sql = std::string("UPDATE topic SET ") + field + " = ?, modified = ? WHERE id = ?";
    Query q(db_, sql.c_str());
    q.bind(1, changes[field].get<std::string>()).bind(2, now()).bind(3, topic).step();
  }
  return true;
}

long ReviewStore::add_comment(long project, long topic, const std::string& text, const json& viewpoint, long user) {
  std::lock_guard lock(mutex_);
  Query exists(db_, "SELECT 1 FROM topic WHERE project = ? AND id = ?");
  if (!exists.bind(1, project).bind(2, topic).step()) return 0;
  Query q(db_, "INSERT INTO comment(topic, text, viewpoint, author, created) VALUES(?, ?, ?, ?, ?)");
  q.bind(1, topic).bind(2, text);
  if (viewpoint.is_null()) q.bind_null(3);
  else q.bind(3, viewpoint.dump());
  q.bind(4, user).bind(5, now()).step();
  const long id = long(sqlite3_last_insert_rowid(db_));
  Query touch(db_, "UPDATE topic SET modified = ? WHERE id = ?");
  touch.bind(1, now()).bind(2, topic).step();
  return id;
}

std::vector<long> ReviewStore::note_on_finding(long project, const std::string& finding_key, const std::string& text) {
  std::vector<long> topics;
  {
    std::lock_guard lock(mutex_);
    Query q(db_, "SELECT id FROM topic WHERE project = ? AND finding = ?");
    q.bind(1, project).bind(2, finding_key);
    while (q.step()) topics.push_back(q.integer(0));
  }
  for (long t : topics) add_comment(project, t, text, nullptr, 0);
  return topics;
}

namespace {
json topic_row(sqlite3* db, Query& q, Role role) {
  json t{{"id", q.integer(0)},
         {"title", q.text(1)},
         {"status", q.text(2)},
         {"assignee", q.text(3)},
         {"finding", q.text(4)},
         {"created_by", name_of(db, q.integer(5))},  // an account: for an imported item, the importer
         {"created", q.real(6)},
         {"modified", q.real(7)},
         {"guid", q.text(8)},
         {"description", q.text(9)},
         {"labels", json::parse(q.text(10))},
         {"due", q.real(11)},
         {"bcf_author", q.text(12)},  // who the BCF file names as its author ("" when made here)
         {"authorization", {{"topic_actions", topic_actions(role)}, {"topic_status", topic_statuses()}}},
         {"comments", json::array()}};
  Query c(db, "SELECT id, text, viewpoint, author, created, guid, author_name FROM comment WHERE topic = ? ORDER BY id");
  c.bind(1, q.integer(0));
  while (c.step())
    t["comments"].push_back({{"id", c.integer(0)},
                             {"text", c.text(1)},
                             {"viewpoint", parse_or_null(c.text(2))},
                             {"author", name_of(db, c.integer(3))},
                             {"created", c.real(4)},
                             {"guid", c.text(5)},
                             {"bcf_author", c.text(6)}});
  return t;
}
constexpr const char* kTopicColumns =
    "SELECT id, title, status, assignee, finding, created_by, created, modified, guid, description, labels, due,"
    " author_name FROM topic ";
}  // namespace

json ReviewStore::topics(long project, Role role) {
  std::lock_guard lock(mutex_);
  json out = json::array();
  const std::string sql = std::string(kTopicColumns) + "WHERE project = ? ORDER BY id";
  Query q(db_, sql.c_str());
  q.bind(1, project);
  while (q.step()) out.push_back(topic_row(db_, q, role));
  return out;
}

namespace {
// BCF's statuses are each tool's own words; these are the review app's four.
std::string status_of(const std::string& bcf) {
  std::string s;
  for (char c : bcf) s += (c == ' ' || c == '-') ? '_' : char(std::tolower(static_cast<unsigned char>(c)));
  if (s == "in_progress" || s == "active" || s == "assigned") return "in_progress";
  if (s == "resolved" || s == "fixed" || s == "done") return "resolved";
  if (s == "closed") return "closed";
  return "open";  // open, reopened, new, and any word this server does not know
}
}  // namespace

json ReviewStore::import_topics(long project, const std::vector<BcfTopic>& topics, long user) {
  std::lock_guard lock(mutex_);
  store::exec(db_, "BEGIN IMMEDIATE;", kWhat);
  json out{{"topics_added", 0}, {"topics_updated", 0}, {"comments_added", 0}, {"topics", json::array()}};
  try {
    // The GUIDs this project's items already answer to: an imported one's own, or the one an
    // export derives from the item's id (a file exported here and read back adds nothing).
    std::map<std::string, long> topic_by_guid;
    std::set<std::string> comment_guids;
    {
      Query q(db_, "SELECT id, guid FROM topic WHERE project = ?");
      q.bind(1, project);
      while (q.step()) {
        const long id = q.integer(0);
        topic_by_guid[q.text(1).empty() ? topic_guid(project, id) : q.text(1)] = id;
      }
      Query c(db_, "SELECT comment.id, comment.guid FROM comment JOIN topic ON topic.id = comment.topic WHERE topic.project = ?");
      c.bind(1, project);
      while (c.step())
        comment_guids.insert(c.text(1).empty() ? comment_guid(project, c.integer(0)) : c.text(1));
    }
    for (const BcfTopic& t : topics) {
      long id = 0;
      const bool known = topic_by_guid.count(t.guid) > 0;
      if (known) {
        id = topic_by_guid[t.guid];
        out["topics_updated"] = out["topics_updated"].get<int>() + 1;
      } else {
        Query q(db_,
                "INSERT INTO topic(project, title, status, assignee, created_by, created, modified, guid, description,"
                " labels, due, author_name) VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?)");
        q.bind(1, project).bind(2, t.title).bind(3, status_of(t.status)).bind(4, t.assignee).bind(5, user);
        q.bind(6, t.created).bind(7, t.modified > 0 ? t.modified : t.created).bind(8, t.guid).bind(9, t.description);
        q.bind(10, json(t.labels).dump()).bind(11, t.due).bind(12, t.author).step();
        id = long(sqlite3_last_insert_rowid(db_));
        topic_by_guid[t.guid] = id;
        out["topics_added"] = out["topics_added"].get<int>() + 1;
      }
      const int comments_before = out["comments_added"].get<int>();
      auto add = [&](const std::string& guid, const std::string& text, const json& viewpoint, const std::string& who,
                     double when) {
        if (!guid.empty() && !comment_guids.insert(guid).second) return;  // already here
        Query q(db_, "INSERT INTO comment(topic, text, viewpoint, author, created, guid, author_name) VALUES(?, ?, ?, ?, ?, ?, ?)");
        q.bind(1, id).bind(2, text);
        if (viewpoint.is_null()) q.bind_null(3);
        else q.bind(3, viewpoint.dump());
        q.bind(4, user).bind(5, when).bind(6, guid).bind(7, who).step();
        out["comments_added"] = out["comments_added"].get<int>() + 1;
      };
      std::set<std::string> shown;
      for (const BcfComment& c : t.comments) {
        add(c.guid, c.text, c.viewpoint.empty() ? json() : t.viewpoints.at(c.viewpoint), c.author, c.date);
        if (!c.viewpoint.empty()) shown.insert(c.viewpoint);
      }
      // A viewpoint no comment shows becomes a comment of its own (named by its GUID: once).
      for (const auto& [guid, camera] : t.viewpoints)
        if (!shown.count(guid) && !camera.is_null()) add(guid, "(a viewpoint of the BCF file)", camera, t.author, t.created);
      out["topics"].push_back({{"id", id}, {"added", !known}, {"comments_added", out["comments_added"].get<int>() - comments_before}});
    }
    store::exec(db_, "COMMIT;", kWhat);
  } catch (...) {
    store::exec(db_, "ROLLBACK;", kWhat);
    throw;
  }
  return out;
}

json ReviewStore::topic(long project, long topic, Role role) {
  std::lock_guard lock(mutex_);
  const std::string sql = std::string(kTopicColumns) + "WHERE project = ? AND id = ?";
  Query q(db_, sql.c_str());
  if (!q.bind(1, project).bind(2, topic).step()) return nullptr;
  return topic_row(db_, q, role);
}

long ReviewStore::add_event(long project, const std::string& type, long actor, const json& data) {
  std::lock_guard lock(mutex_);
  Query q(db_, "INSERT INTO event(project, time, actor, type, data) VALUES(?, ?, ?, ?, ?)");
  q.bind(1, project).bind(2, now()).bind(3, actor).bind(4, type).bind(5, data.dump()).step();
  return long(sqlite3_last_insert_rowid(db_));
}

std::vector<Event> ReviewStore::events_after(long project, long after, int limit) {
  std::lock_guard lock(mutex_);
  std::vector<Event> out;
  Query q(db_, "SELECT id, type, data FROM event WHERE project = ? AND id > ? ORDER BY id LIMIT ?");
  q.bind(1, project).bind(2, after).bind(3, limit);
  while (q.step()) out.push_back({q.integer(0), q.text(1), json::parse(q.text(2))});
  return out;
}

long ReviewStore::last_event(long project) {
  std::lock_guard lock(mutex_);
  Query q(db_, "SELECT coalesce(max(id), 0) FROM event WHERE project = ?");
  return q.bind(1, project).step() ? q.integer(0) : 0;
}

}  // namespace mtcs::serve
