#pragma once
// The review server's database (SQLite, WAL, one connection behind a mutex): accounts, sessions
// and API tokens (digests only), projects and their members, every uploaded version of a
// component (immutable, by content hash), checks run on the server (jobs) and what they found
// (findings, with the durable key that follows a problem from one version to the next), review
// items (topics) with their comments and viewpoints, and the event log that live pages replay.
// Every statement is prepared; no user text is ever spliced into SQL.

#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "mtcs/serve/bcf_import.h"
#include "mtcs/serve/roles.h"

struct sqlite3;

namespace mtcs::serve {

struct User {
  long id = 0;
  std::string name;
  Role role = Role::viewer;  // on the server: an owner owns every project
};

struct Session {
  User user;
  std::string csrf;
};

struct Version {
  long id = 0, project = 0, seq = 0, size = 0;
  std::string component, kind, blob, filename;
};

struct Job {
  long id = 0, project = 0;
  std::string kind, state, scope;
  nlohmann::json inputs;
};

// One problem a check found, with the key that names it across versions, and what became of it
// against the last check of the same scope: new, persistent (found again) or resolved (there
// before, not found now).
struct Finding {
  std::string key, state;
  nlohmann::json payload;
};

struct Event {
  long id = 0;
  std::string type;
  nlohmann::json data;
};

class ReviewStore {
 public:
  explicit ReviewStore(const std::filesystem::path& file);
  ~ReviewStore();
  ReviewStore(const ReviewStore&) = delete;
  ReviewStore& operator=(const ReviewStore&) = delete;

  // Accounts. add_user throws std::invalid_argument when the name is taken.
  long add_user(const std::string& name, const std::string& password_hash, Role role);
  std::optional<User> user(const std::string& name, std::string* password_hash = nullptr);
  long user_count();

  void add_session(const std::string& digest, long user, const std::string& csrf);
  // A session unused for max_idle_seconds, or older than max_age_seconds, is over.
  std::optional<Session> session(const std::string& digest, double max_idle_seconds, double max_age_seconds);
  void drop_session(const std::string& digest);
  void add_token(const std::string& digest, long user, const std::string& name);
  std::optional<User> token_user(const std::string& digest);

  // Projects; a user's role on one (nullopt: not a member).
  long add_project(const std::string& name, long owner);
  std::optional<Role> role_on(long project, const User& user);
  nlohmann::json projects_of(const User& user);
  nlohmann::json project(long project);
  void set_member(long project, long user, Role role);

  // Versions: the next seq of the component; equal content to its latest version is not a new one.
  Version add_version(long project, const std::string& component, const std::string& kind, const std::string& blob,
                      const std::string& filename, long size, long user, bool* existed = nullptr);
  std::optional<Version> version(long project, long id);
  std::optional<Version> latest(long project, const std::string& component);
  nlohmann::json components(long project);

  // Jobs: queued -> running -> succeeded | failed | cancelled | interrupted.
  long add_job(long project, const std::string& kind, const nlohmann::json& inputs, const std::string& scope, long user);
  std::optional<Job> job(long project, long id);
  // The oldest queued job, now marked running (atomically: two workers never take one job).
  std::optional<Job> claim_next();
  nlohmann::json job_json(long project, long id);
  nlohmann::json jobs(long project);
  long queued_jobs(long project);
  void set_job_state(long id, const std::string& state, const std::string& message = "",
                     const nlohmann::json& result = nullptr);
  // Cancels a job still queued (atomically against claim_next); false when it is not queued.
  bool cancel_queued(long project, long id);
  // At start: jobs a killed server left running are marked interrupted; them.
  std::vector<Job> interrupt_running();
  // Stores a finished check's findings, each stated against the last succeeded job of its scope.
  std::vector<Finding> settle_findings(const Job& job, std::vector<Finding> found);
  nlohmann::json findings(long project, long job);

  // Review items.
  long add_topic(long project, const std::string& title, const std::string& finding_key, long user);
  bool update_topic(long project, long topic, const nlohmann::json& changes);
  long add_comment(long project, long topic, const std::string& text, const nlohmann::json& viewpoint, long user);
  // A comment by mtcs itself on every item of the project that follows this finding; their ids.
  std::vector<long> note_on_finding(long project, const std::string& finding_key, const std::string& text);
  nlohmann::json topics(long project, Role role);
  // A BCF file's items into the project, in one transaction: an item whose GUID the project knows
  // (imported before, or exported from here) gains only the comments it lacks; the others are
  // added with their dates, labels and viewpoints. The importer's account is their author; the
  // file's names stay beside it (bcf_author), never as an account.
  // {topics_added, topics_updated, comments_added, topics: [{id, added, comments_added}] in the file's order}.
  nlohmann::json import_topics(long project, const std::vector<BcfTopic>& topics, long user);
  nlohmann::json topic(long project, long topic, Role role);

  // The event log of a project.
  long add_event(long project, const std::string& type, long actor, const nlohmann::json& data);
  std::vector<Event> events_after(long project, long after, int limit);
  long last_event(long project);

 private:
  std::mutex mutex_;
  sqlite3* db_ = nullptr;
};

}  // namespace mtcs::serve
