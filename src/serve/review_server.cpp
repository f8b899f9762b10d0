#include "mtcs/serve/review_server.h"

#include <fcntl.h>
#include <httplib.h>
#include <sys/file.h>
#include <pthread.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <fstream>
#include <map>
#include <mutex>
#include <regex>
#include <semaphore>
#include <stdexcept>
#include <thread>

#include <nlohmann/json.hpp>

#include "assets.h"
#include "mtcs/serve/bcf_export.h"
#include "mtcs/serve/bcf_import.h"
#include "mtcs/serve/blob_store.h"
#include "mtcs/serve/credentials.h"
#include "mtcs/serve/event_broker.h"
#include "mtcs/serve/job_runner.h"
#include "mtcs/serve/review_store.h"
#include "mtcs/serve/upload_check.h"

namespace mtcs::serve {
namespace fs = std::filesystem;
using nlohmann::json;
using httplib::Request;
using httplib::Response;

namespace {

constexpr double kSessionIdleSeconds = 12 * 3600, kSessionAgeSeconds = 7 * 24 * 3600;
constexpr const char* kCookie = "mtcs_session";
constexpr int kQueuedJobsPerProject = 8;

// A request refused with an HTTP status and a message the page can show.
struct Refusal : std::runtime_error {
  Refusal(int status, const std::string& what) : std::runtime_error(what), status(status) {}
  int status;
};

// Who called, and as what on the project the route names (0: none).
struct Caller {
  User user;
  std::optional<Session> session;  // empty for an API token
  long project = 0;
  Role role = Role::viewer;
};

void reply(Response& res, int status, const json& body) {
  res.status = status;
  res.set_content(body.dump(), "application/json");
}

json body_json(const Request& req) {
  const std::string type = req.get_header_value("Content-Type");
  if (type.rfind("application/json", 0) != 0) throw Refusal(415, "send the body as application/json");
  try {
    json j = json::parse(req.body);
    if (!j.is_object()) throw Refusal(400, "the body must be a JSON object");
    return j;
  } catch (const json::parse_error& e) {
    throw Refusal(400, std::string("malformed JSON: ") + e.what());
  }
}

std::string text_field(const json& j, const char* field, std::size_t max, bool required = true) {
  if (!j.contains(field)) {
    if (required) throw Refusal(400, std::string("field '") + field + "' is missing");
    return "";
  }
  if (!j[field].is_string()) throw Refusal(400, std::string("field '") + field + "' must be a string");
  std::string s = j[field].get<std::string>();
  if (s.size() > max) throw Refusal(400, std::string("field '") + field + "' is longer than " + std::to_string(max) + " bytes");
  if (required && s.empty()) throw Refusal(400, std::string("field '") + field + "' is empty");
  return s;
}

std::string cookie_value(const Request& req, const std::string& name) {
  const std::string header = req.get_header_value("Cookie");
  std::size_t at = 0;
  while (at < header.size()) {
    const std::size_t end = std::min(header.find(';', at), header.size());
    std::string part = header.substr(at, end - at);
    part.erase(0, part.find_first_not_of(' '));
    if (part.rfind(name + "=", 0) == 0) return part.substr(name.size() + 1);
    at = end + 1;
  }
  return "";
}

// A stored file sent in pieces, never whole in memory.
void send_file(Response& res, const fs::path& file, const char* type) {
  auto in = std::make_shared<std::ifstream>(file, std::ios::binary);
  if (!*in) throw Refusal(404, "the stored file is missing");
  const auto size = std::size_t(fs::file_size(file));
  res.set_content_provider(size, type, [in](std::size_t offset, std::size_t length, httplib::DataSink& sink) {
    std::vector<char> piece(std::min<std::size_t>(length, 1u << 16));
    in->seekg(std::streamoff(offset));
    in->read(piece.data(), std::streamsize(piece.size()));
    return in->gcount() > 0 && sink.write(piece.data(), std::size_t(in->gcount()));
  });
}

bool is_mesh_extension(const std::string& ext) { return ext == ".stl" || ext == ".off" || ext == ".obj" || ext == ".ply"; }

std::string lower(std::string s) {
  for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// Failed logins per account and per address: five a minute, then 429 until the minute is over.
class LoginLimiter {
 public:
  bool allowed(const std::string& key) {
    std::lock_guard lock(mutex_);
    auto& [count, since] = failures_[key];
    if (std::chrono::steady_clock::now() - since > std::chrono::minutes(1)) count = 0;
    return count < 5;
  }
  void failed(const std::string& key) {
    std::lock_guard lock(mutex_);
    if (failures_.size() > 100000) failures_.clear();  // a flood of names must not grow it without end
    auto& [count, since] = failures_[key];
    if (count == 0) since = std::chrono::steady_clock::now();
    ++count;
  }

 private:
  std::mutex mutex_;
  std::map<std::string, std::pair<int, std::chrono::steady_clock::time_point>> failures_;
};

}  // namespace

const std::vector<RouteInfo>& route_table() {
  static const std::vector<RouteInfo> table{
      {"GET", "/", "/", Access::open},
      {"GET", "/app.js", "/app.js", Access::open},
      {"GET", "/app.css", "/app.css", Access::open},
      {"GET", "/favicon.svg", "/favicon.svg", Access::open},
      {"POST", "/api/v1/login", "/api/v1/login", Access::open},
      {"POST", "/api/v1/logout", "/api/v1/logout", Access::signed_in},
      {"GET", "/api/v1/me", "/api/v1/me", Access::signed_in},
      {"POST", "/api/v1/tokens", "/api/v1/tokens", Access::signed_in},
      {"GET", "/api/v1/projects", "/api/v1/projects", Access::signed_in},
      {"POST", "/api/v1/projects", "/api/v1/projects", Access::creator},
      {"GET", R"(/api/v1/projects/(\d+))", "/api/v1/projects/1", Access::member, Role::viewer},
      {"PUT", R"(/api/v1/projects/(\d+)/members)", "/api/v1/projects/1/members", Access::member, Role::owner},
      {"GET", R"(/api/v1/projects/(\d+)/components)", "/api/v1/projects/1/components", Access::member, Role::viewer},
      {"POST", R"(/api/v1/projects/(\d+)/components/([A-Za-z0-9_.-]{1,64})/versions)",
       "/api/v1/projects/1/components/core/versions", Access::member, Role::designer},
      {"GET", R"(/api/v1/projects/(\d+)/versions/(\d+)/file)", "/api/v1/projects/1/versions/1/file", Access::member,
       Role::viewer},
      {"GET", R"(/api/v1/projects/(\d+)/jobs)", "/api/v1/projects/1/jobs", Access::member, Role::viewer},
      {"POST", R"(/api/v1/projects/(\d+)/jobs)", "/api/v1/projects/1/jobs", Access::member, Role::designer},
      {"GET", R"(/api/v1/projects/(\d+)/jobs/(\d+))", "/api/v1/projects/1/jobs/1", Access::member, Role::viewer},
      {"GET", R"(/api/v1/projects/(\d+)/jobs/(\d+)/page)", "/api/v1/projects/1/jobs/1/page", Access::member,
       Role::viewer},
      {"POST", R"(/api/v1/projects/(\d+)/jobs/(\d+)/cancel)", "/api/v1/projects/1/jobs/1/cancel", Access::member,
       Role::designer},
      {"GET", R"(/api/v1/projects/(\d+)/topics)", "/api/v1/projects/1/topics", Access::member, Role::viewer},
      {"GET", R"(/api/v1/projects/(\d+)/bcf)", "/api/v1/projects/1/bcf", Access::member, Role::viewer},
      {"POST", R"(/api/v1/projects/(\d+)/bcf)", "/api/v1/projects/1/bcf", Access::member, Role::reviewer},
      {"POST", R"(/api/v1/projects/(\d+)/topics)", "/api/v1/projects/1/topics", Access::member, Role::reviewer},
      {"GET", R"(/api/v1/projects/(\d+)/topics/(\d+))", "/api/v1/projects/1/topics/1", Access::member, Role::viewer},
      {"PATCH", R"(/api/v1/projects/(\d+)/topics/(\d+))", "/api/v1/projects/1/topics/1", Access::member,
       Role::reviewer},
      {"POST", R"(/api/v1/projects/(\d+)/topics/(\d+)/comments)", "/api/v1/projects/1/topics/1/comments",
       Access::member, Role::reviewer},
      {"GET", R"(/api/v1/projects/(\d+)/events)", "/api/v1/projects/1/events", Access::member, Role::viewer},
  };
  return table;
}

namespace {
const std::regex& bcf_route() {
  static const std::regex r(R"(/api/v1/projects/\d+/bcf)");
  return r;
}

const std::regex& upload_route() {
  static const std::regex pattern(R"(/api/v1/projects/(\d+)/components/([A-Za-z0-9_.-]{1,64})/versions)");
  return pattern;
}
}  // namespace

// One server per data folder: an advisory lock on DIR/serve.lock for the server's life (the
// kernel drops it when the process dies, kill -9 included).
class FolderLock {
 public:
  explicit FolderLock(const fs::path& data) {
    fs::create_directories(data);
    fd_ = ::open((data / "serve.lock").c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0600);
    if (fd_ < 0 || ::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      if (fd_ >= 0) ::close(fd_);
      throw BindError(data.string() + " is served by another mtcs serve already");
    }
  }
  ~FolderLock() { ::close(fd_); }
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  int fd_ = -1;
};

// Whether something accepts connections at address:port (httplib binds with SO_REUSEPORT's
// sharing on some builds: a second server would split the first one's traffic silently).
bool answered(const std::string& address, int port) {
  httplib::Client probe(address, port);
  probe.set_connection_timeout(0, 200000);
  return static_cast<bool>(probe.Get("/favicon.svg"));
}

struct ReviewServer::Impl {
  ServeOptions options;
  FolderLock lock;
  BlobStore blobs;
  ReviewStore store;
  EventBroker events;
  JobRunner jobs;
  httplib::Server http;
  std::counting_semaphore<2> hashing{2};  // Argon2id takes 64 MiB a hash
  LoginLimiter limiter;
  std::atomic<int> streams{0};
  std::atomic<bool> listening{false}, stop_asked{false};
  std::string dummy_hash;  // an unknown user's login costs what a known one's does

  explicit Impl(ServeOptions o)
      : options(std::move(o)),
        lock(options.data),
        blobs(options.data),
        store(options.data / "serve.sqlite"),
        events(store),
        jobs(store, events, blobs, options.mtcs_binary, options.jobs),
        dummy_hash(hash_password(random_token())) {
    http.set_tcp_nodelay(true);  // without it Nagle meets delayed ACK: 40 ms a small reply
    const int threads = options.threads;
    http.new_task_queue = [threads] { return new httplib::ThreadPool(std::size_t(threads)); };
    // httplib caps every body at one length: the uploads'. A JSON route's body is read before
    // its handler runs, so the gate below refuses a larger or unannounced (chunked) one first.
    // The gate and the upload's own count trip first.
    http.set_payload_max_length(std::max({options.upload_bytes, options.bcf_bytes, options.body_bytes}) + (1u << 20));
    http.set_pre_routing_handler([this](const Request& req, Response& res) { return gate_body(req, res); });
    http.set_read_timeout(10);
    http.set_keep_alive_max_count(100);
    http.set_default_headers({{"X-Content-Type-Options", "nosniff"}, {"Cache-Control", "no-store"}});
    http.set_post_routing_handler([](const Request&, Response& res) {
      if (!res.has_header("Content-Security-Policy"))
        res.set_header("Content-Security-Policy", "default-src 'self'; object-src 'none'; frame-ancestors 'none'");
    });
    http.set_exception_handler([](const Request&, Response& res, std::exception_ptr ep) {
      try {
        std::rethrow_exception(ep);
      } catch (const std::exception& e) {
        reply(res, 500, {{"error", std::string("internal error: ") + e.what()}});
      } catch (...) {
        reply(res, 500, {{"error", "internal error"}});
      }
    });
    http.set_error_handler([](const Request&, Response& res) {
      if (res.body.empty()) reply(res, res.status, json{{"error", res.status == 404 ? "no such route" : "refused"}});
    });
    for (const RouteInfo& route : route_table()) add(route);
  }

  // Before any body is read: a JSON route's body must announce its length and stay under
  // body_bytes (httplib reads it before the handler runs); an upload's is counted as it arrives,
  // so it may be chunked. A refused body is never read: the connection closes after the answer.
  httplib::Server::HandlerResponse gate_body(const Request& req, Response& res) {
    const bool upload = req.method == "POST" && std::regex_match(req.path, upload_route());
    const bool bcf = req.method == "POST" && std::regex_match(req.path, bcf_route());
    const std::size_t cap = upload ? options.upload_bytes : bcf ? options.bcf_bytes : options.body_bytes;
    const bool chunked = lower(req.get_header_value("Transfer-Encoding")).find("chunked") != std::string::npos;
    const bool sized = req.has_header("Content-Length");
    const unsigned long long length = sized ? std::strtoull(req.get_header_value("Content-Length").c_str(), nullptr, 10) : 0;
    const bool may_have_body = req.method == "POST" || req.method == "PUT" || req.method == "PATCH" || req.method == "DELETE";
    int status = 0;
    std::string why;
    if (req.has_header("Transfer-Encoding") && !(upload && chunked && !sized))
      status = 411, why = upload ? "send the file chunked or with a Content-Length, not both" : "send the body with a Content-Length";
    else if (may_have_body && !sized && !upload)
      status = 411, why = "send the body with a Content-Length";
    else if (upload && !sized && !chunked)
      status = 411, why = "send the file with a Content-Length or chunked";
    else if (length > cap)
      status = 413, why = "the body is larger than " + std::to_string(cap) + " bytes";
    if (status == 0) return httplib::Server::HandlerResponse::Unhandled;
    res.set_header("Connection", "close");
    reply(res, status, {{"error", why}});
    return httplib::Server::HandlerResponse::Handled;
  }

  // The gate every route passes: identify, check CSRF on a session's writes, check the role.
  Caller admit(const RouteInfo& route, const Request& req) {
    Caller caller;
    if (route.access == Access::open) return caller;
    const std::string auth = req.get_header_value("Authorization");
    if (auth.rfind("Bearer ", 0) == 0) {
      auto user = store.token_user(token_digest(auth.substr(7)));
      if (!user) throw Refusal(401, "unknown API token");
      caller.user = *user;
    } else {
      const std::string token = cookie_value(req, kCookie);
      if (token.empty()) throw Refusal(401, "sign in first");
      caller.session = store.session(token_digest(token), kSessionIdleSeconds, kSessionAgeSeconds);
      if (!caller.session) throw Refusal(401, "the session has ended; sign in again");
      caller.user = caller.session->user;
      if (req.method != "GET") {
        if (!same_secret(req.get_header_value("X-MTCS-CSRF"), caller.session->csrf))
          throw Refusal(403, "missing or wrong X-MTCS-CSRF header");
        const std::string site = req.get_header_value("Sec-Fetch-Site");
        if (!site.empty() && site != "same-origin" && site != "none") throw Refusal(403, "a request from another site");
      }
    }
    if (route.access == Access::creator && !at_least(caller.user.role, Role::designer))
      throw Refusal(403, "creating projects needs the server role designer or owner");
    if (route.access == Access::member) {
      caller.project = std::stol(req.matches[1]);
      const auto role = store.role_on(caller.project, caller.user);
      if (!role) throw Refusal(404, "no such project");
      caller.role = *role;
      if (!at_least(*role, route.least))
        throw Refusal(403, "this needs the role " + to_string(route.least) + " on the project (you are " +
                               to_string(*role) + ")");
    }
    return caller;
  }

  void add(const RouteInfo& route) {
    const bool streamed = route.method == "POST" && std::regex_match(route.example, upload_route());
    if (streamed) {
      http.Post(route.pattern, [this, route](const Request& req, Response& res, const httplib::ContentReader& read) {
        guarded(res, [&] { upload(admit(route, req), req, res, read); });
        if (res.status >= 400) res.set_header("Connection", "close");  // the body may be unread
      });
      return;
    }
    auto handler = [this, route](const Request& req, Response& res) {
      guarded(res, [&] { dispatch(route, admit(route, req), req, res); });
    };
    if (route.method == "GET") http.Get(route.pattern, handler);
    else if (route.method == "POST") http.Post(route.pattern, handler);
    else if (route.method == "PUT") http.Put(route.pattern, handler);
    else if (route.method == "PATCH") http.Patch(route.pattern, handler);
  }

  template <class F>
  static void guarded(Response& res, F&& f) {
    try {
      f();
    } catch (const Refusal& r) {
      reply(res, r.status, {{"error", r.what()}});
    } catch (const json::exception& e) {
      reply(res, 400, {{"error", std::string("a field has the wrong type: ") + e.what()}});
    }
  }

  void dispatch(const RouteInfo& route, const Caller& caller, const Request& req, Response& res) {
    const std::string& p = route.pattern;
    const std::string& m = route.method;
    if (p == "/") return res.set_content(assets::text("app.html"), "text/html; charset=utf-8");
    if (p == "/app.js") return res.set_content(assets::text("app.js"), "text/javascript; charset=utf-8");
    if (p == "/app.css") return res.set_content(assets::text("app.css"), "text/css; charset=utf-8");
    if (p == "/favicon.svg") return res.set_content(assets::text("favicon.svg"), "image/svg+xml");
    if (p == "/api/v1/login") return login(req, res);
    if (p == "/api/v1/logout") return logout(req, res);
    if (p == "/api/v1/me") return reply(res, 200, me(caller));
    if (p == "/api/v1/tokens") return new_token(caller, req, res);
    if (p == "/api/v1/projects") {
      if (m == "GET") return reply(res, 200, store.projects_of(caller.user));
      return new_project(caller, req, res);
    }
    const long project = caller.project;
    const std::string tail = p.substr(std::string(R"(/api/v1/projects/(\d+))").size());
    if (tail.empty()) {
      json out = store.project(project);
      out["role"] = to_string(caller.role);
      out["last_event"] = store.last_event(project);
      out["topic_actions"] = topic_actions(caller.role);
      return reply(res, 200, out);
    }
    if (tail == "/members") return set_member(caller, req, res);
    if (tail == "/components") return reply(res, 200, store.components(project));
    if (tail == R"(/versions/(\d+)/file)") return version_file(caller, req, res);
    if (tail == "/jobs") {
      if (m == "GET") return reply(res, 200, store.jobs(project));
      return new_job(caller, req, res);
    }
    if (tail == R"(/jobs/(\d+))") {
      const long id = std::stol(req.matches[2]);
      json job = store.job_json(project, id);
      if (job.is_null()) throw Refusal(404, "no such job");
      job["findings"] = store.findings(project, id);
      return reply(res, 200, job);
    }
    if (tail == R"(/jobs/(\d+)/cancel)") return cancel_job(caller, req, res);
    if (tail == R"(/jobs/(\d+)/page)") return job_page(caller, req, res);
    if (tail == "/topics") {
      if (m == "GET") return reply(res, 200, store.topics(project, caller.role));
      return new_topic(caller, req, res);
    }
    if (tail == R"(/topics/(\d+))") {
      if (m == "GET") {
        json t = store.topic(project, std::stol(req.matches[2]), caller.role);
        if (t.is_null()) throw Refusal(404, "no such review item");
        return reply(res, 200, t);
      }
      return update_topic(caller, req, res);
    }
    if (tail == R"(/topics/(\d+)/comments)") return new_comment(caller, req, res);
    if (tail == "/events") return stream(caller, req, res);
    if (tail == "/bcf" && m == "POST") return import_bcf(caller, req, res);
    if (tail == "/bcf") {
      res.set_header("Content-Disposition", "attachment; filename=\"project-" + std::to_string(project) + ".bcf\"");
      return res.set_content(bcf_archive(project, store.topics(project, caller.role), (blobs.root() / "tmp").string()),
                             "application/octet-stream");
    }
    throw Refusal(404, "no such route");
  }

  static json me(const Caller& c) {
    json out{{"user", c.user.name}, {"role", to_string(c.user.role)}};
    if (c.session) out["csrf"] = c.session->csrf;
    return out;
  }

  void login(const Request& req, Response& res) {
    const json body = body_json(req);
    const std::string name = text_field(body, "name", 64), password = text_field(body, "password", 1024);
    // Behind nginx every request comes from 127.0.0.1: the proxy's X-Real-IP names the client.
    const std::string address = (req.remote_addr == "127.0.0.1" || req.remote_addr == "::1") && req.has_header("X-Real-IP")
                                    ? req.get_header_value("X-Real-IP")
                                    : req.remote_addr;
    if (!limiter.allowed("user:" + name) || !limiter.allowed("addr:" + address))
      throw Refusal(429, "too many failed sign-ins; wait a minute");
    std::string stored;
    const auto user = store.user(name, &stored);
    bool ok;
    {
      hashing.acquire();
      ok = verify_password(user ? stored : dummy_hash, password) && user.has_value();
      hashing.release();
    }
    if (!ok) {
      limiter.failed("user:" + name);
      limiter.failed("addr:" + address);
      throw Refusal(401, "wrong name or password");
    }
    const std::string token = random_token(), csrf = random_token();
    store.add_session(token_digest(token), user->id, csrf);
    res.set_header("Set-Cookie", std::string(kCookie) + "=" + token + "; Path=/; HttpOnly; SameSite=Strict" +
                                     (options.secure_cookie ? "; Secure" : ""));
    reply(res, 200, {{"user", user->name}, {"role", to_string(user->role)}, {"csrf", csrf}});
  }

  void logout(const Request& req, Response& res) {
    const std::string token = cookie_value(req, kCookie);
    if (!token.empty()) store.drop_session(token_digest(token));
    res.set_header("Set-Cookie", std::string(kCookie) + "=; Path=/; HttpOnly; SameSite=Strict; Max-Age=0");
    reply(res, 200, {{"signed_out", true}});
  }

  void new_token(const Caller& caller, const Request& req, Response& res) {
    if (!caller.session) throw Refusal(403, "API tokens are made from a signed-in session");
    const std::string name = text_field(body_json(req), "name", 64);
    const std::string token = random_token();
    store.add_token(token_digest(token), caller.user.id, name);
    reply(res, 201, {{"name", name}, {"token", token}});
  }

  void new_project(const Caller& caller, const Request& req, Response& res) {
    const std::string name = text_field(body_json(req), "name", 128);
    try {
      const long id = store.add_project(name, caller.user.id);
      reply(res, 201, {{"id", id}, {"name", name}});
    } catch (const std::invalid_argument& e) {
      throw Refusal(409, e.what());
    }
  }

  void set_member(const Caller& caller, const Request& req, Response& res) {
    const json body = body_json(req);
    const auto user = store.user(text_field(body, "user", 64));
    if (!user) throw Refusal(404, "no such user");
    const auto role = role_from(text_field(body, "role", 16));
    if (!role) throw Refusal(400, "field 'role': one of viewer, reviewer, designer, owner");
    store.set_member(caller.project, user->id, *role);
    events.publish(caller.project, "member.updated", caller.user.id, {{"user", user->name}, {"role", to_string(*role)}});
    reply(res, 200, store.project(caller.project));
  }

  // A new version of a component: streamed to a staged file, counted against the limit as it
  // arrives, read back by the CLI's own readers, and stored only if they accept it.
  void upload(const Caller& caller, const Request& req, Response& res, const httplib::ContentReader& read) {
    const std::string component = req.matches[2];
    const std::string filename = req.get_param_value("file");
    if (filename.empty() || filename.size() > 255 || filename.find_first_of("/\\") != std::string::npos ||
        filename.find('\0') != std::string::npos)
      throw Refusal(400, "give the file's name as ?file=NAME.stl (no folders)");
    const std::string ext = lower(fs::path(filename).extension().string());
    if (!is_mesh_extension(ext)) throw Refusal(415, "a component is a mesh: STL, OFF, OBJ or PLY");
    BlobStore::Upload staged = blobs.begin(options.upload_bytes, ext);
    bool too_big = false;
    const bool whole = read([&](const char* data, std::size_t n) {
      if (!staged.write(data, n)) too_big = true;
      return !too_big;
    });
    if (too_big) throw Refusal(413, "the file is larger than " + std::to_string(options.upload_bytes >> 20) + " MiB");
    if (!whole) throw Refusal(400, "the upload was cut short");
    json stats;
    try {
      stats = check_component(staged.staged());
    } catch (const std::runtime_error& e) {
      std::string message = e.what();
      for (std::size_t at; (at = message.find(staged.staged().string())) != std::string::npos;)
        message.replace(at, staged.staged().string().size(), filename);
      throw Refusal(400, filename + ": " + message);
    }
    const long size = long(staged.size());
    const std::string hash = staged.commit();
    bool existed = false;
    const Version v = store.add_version(caller.project, component, "mesh", hash, filename, size, caller.user.id, &existed);
    json out{{"id", v.id}, {"component", v.component}, {"seq", v.seq}, {"blob", v.blob},
             {"size", v.size}, {"filename", v.filename}, {"stats", stats}, {"new", !existed}};
    if (!existed) events.publish(caller.project, "version.created", caller.user.id, out);
    reply(res, existed ? 200 : 201, out);
  }

  void version_file(const Caller& caller, const Request& req, Response& res) {
    const auto v = store.version(caller.project, std::stol(req.matches[2]));
    if (!v) throw Refusal(404, "no such version");
    res.set_header("ETag", "\"" + v->blob + "\"");
    res.set_header("Content-Disposition", "attachment; filename=\"version-" + std::to_string(v->id) +
                                              fs::path(v->filename).extension().string() + "\"");
    send_file(res, blobs.path_of(v->blob), "application/octet-stream");
  }

  Version version_of(long project, const json& ref, const char* field) {
    std::optional<Version> v;
    if (ref.is_string()) v = store.latest(project, ref.get<std::string>());
    else if (ref.is_number_integer()) v = store.version(project, ref.get<long>());
    else throw Refusal(400, std::string("field '") + field + "': a component's name or a version id");
    if (!v) throw Refusal(404, std::string("field '") + field + "': no such component or version");
    return *v;
  }

  void new_job(const Caller& caller, const Request& req, Response& res) {
    const json body = body_json(req);
    if (text_field(body, "kind", 32) != "interference") throw Refusal(400, "field 'kind': interference");
    if (!body.contains("a") || !body.contains("b")) throw Refusal(400, "fields 'a' and 'b': the two components");
    const Version a = version_of(caller.project, body["a"], "a"), b = version_of(caller.project, body["b"], "b");
    json translate = body.value("translate", json::array({0.0, 0.0, 0.0}));
    if (!translate.is_array() || translate.size() != 3)
      throw Refusal(400, "field 'translate': three numbers (mm)");
    for (const auto& t : translate)
      if (!t.is_number() || !std::isfinite(t.get<double>())) throw Refusal(400, "field 'translate': three finite numbers");
    json inputs{{"a", a.id}, {"b", b.id}, {"translate", translate}, {"components", {a.component, b.component}}};
    for (auto& t : translate) t = t.get<double>();  // 0 and 0.0 are one placement
    std::string scope = "interference|" + a.component + "|" + b.component + "|" + translate.dump();
    if (body.contains("touch_tolerance")) {
      const auto& t = body["touch_tolerance"];
      if (!t.is_number() || t.get<double>() < 0) throw Refusal(400, "field 'touch_tolerance': a number >= 0 (mm)");
      inputs["touch_tolerance"] = t.get<double>();
      scope += "|" + inputs["touch_tolerance"].dump();
    }
    const long queued = store.queued_jobs(caller.project);
    if (queued >= kQueuedJobsPerProject) throw Refusal(429, "the project has " + std::to_string(queued) + " checks waiting");
    const long id = store.add_job(caller.project, "interference", inputs, scope, caller.user.id);
    events.publish(caller.project, "job.queued", caller.user.id,
                   {{"job", id}, {"kind", "interference"}, {"a", a.component}, {"b", b.component}});
    jobs.wake();
    reply(res, 202, store.job_json(caller.project, id));
  }

  // The check's own page (mtcs interfere --report): self-contained, its scripts inline, so it
  // gets a CSP of its own; the app frames it (same origin) to read and set its camera.
  void job_page(const Caller& caller, const Request& req, Response& res) {
    const long id = std::stol(req.matches[2]);
    const auto job = store.job(caller.project, id);
    if (!job) throw Refusal(404, "no such job");
    const fs::path page = blobs.root() / "jobs" / std::to_string(id) / "page.html";
    if (job->state != "succeeded" || !fs::exists(page)) throw Refusal(404, "the check has no page (" + job->state + ")");
    res.set_header("Content-Security-Policy",
                   "default-src 'none'; script-src 'unsafe-inline' data:; style-src 'unsafe-inline'; img-src data:; "
                   "frame-ancestors 'self'");
    send_file(res, page, "text/html; charset=utf-8");
  }

  void cancel_job(const Caller& caller, const Request& req, Response& res) {
    const long id = std::stol(req.matches[2]);
    const auto job = store.job(caller.project, id);
    if (!job) throw Refusal(404, "no such job");
    if (store.cancel_queued(caller.project, id))
      events.publish(caller.project, "job.finished", caller.user.id, {{"job", id}, {"state", "cancelled"}});
    else if (!jobs.cancel(id))
      throw Refusal(409, "the job has ended (" + store.job(caller.project, id)->state + ")");
    reply(res, 202, {{"job", id}, {"cancel", true}});
  }

  void new_topic(const Caller& caller, const Request& req, Response& res) {
    const json body = body_json(req);
    const std::string title = text_field(body, "title", 256);
    const std::string finding = text_field(body, "finding", 64, false);
    const long id = store.add_topic(caller.project, title, finding, caller.user.id);
    if (body.contains("comment") || body.contains("viewpoint"))
      store.add_comment(caller.project, id, text_field(body, "comment", 8192, false), body.value("viewpoint", json()),
                        caller.user.id);
    const json topic = store.topic(caller.project, id, caller.role);
    events.publish(caller.project, "topic.created", caller.user.id, topic);
    reply(res, 201, topic);
  }

  // A BCF file's items into the project (its bytes are the body); each item added or followed
  // goes to the live pages as it would if made here.
  void import_bcf(const Caller& caller, const Request& req, Response& res) {
    std::vector<BcfTopic> topics;
    try {
      topics = read_bcf(req.body);
    } catch (const BcfError& e) {
      throw Refusal(400, std::string("the BCF file: ") + e.what());
    }
    const json summary = store.import_topics(caller.project, topics, caller.user.id);
    for (const json& t : summary["topics"]) {
      if (!t["added"].get<bool>() && t["comments_added"].get<int>() == 0) continue;  // nothing new
      const json topic = store.topic(caller.project, t["id"].get<long>(), caller.role);
      events.publish(caller.project, t["added"].get<bool>() ? "topic.created" : "topic.updated", caller.user.id, topic);
    }
    reply(res, 200, summary);
  }

  void update_topic(const Caller& caller, const Request& req, Response& res) {
    const json body = body_json(req);
    json changes;
    if (body.contains("title")) changes["title"] = text_field(body, "title", 256);
    if (body.contains("assignee")) changes["assignee"] = text_field(body, "assignee", 64, false);
    if (body.contains("status")) {
      const std::string status = text_field(body, "status", 32);
      const auto& allowed = topic_statuses();
      if (std::find(allowed.begin(), allowed.end(), status) == allowed.end())
        throw Refusal(400, "field 'status': one of open, in_progress, resolved, closed");
      changes["status"] = status;
    }
    const long id = std::stol(req.matches[2]);
    if (!store.update_topic(caller.project, id, changes)) throw Refusal(404, "no such review item");
    const json topic = store.topic(caller.project, id, caller.role);
    events.publish(caller.project, "topic.updated", caller.user.id, topic);
    reply(res, 200, topic);
  }

  void new_comment(const Caller& caller, const Request& req, Response& res) {
    const json body = body_json(req);
    const std::string text = text_field(body, "text", 8192);
    const json viewpoint = body.value("viewpoint", json());
    if (!viewpoint.is_null() && !viewpoint.is_object()) throw Refusal(400, "field 'viewpoint': an object");
    const long topic = std::stol(req.matches[2]);
    const long id = store.add_comment(caller.project, topic, text, viewpoint, caller.user.id);
    if (id == 0) throw Refusal(404, "no such review item");
    const json out{{"topic", topic}, {"comment", id}, {"text", text}, {"author", caller.user.name}, {"viewpoint", viewpoint}};
    events.publish(caller.project, "comment.created", caller.user.id, out);
    reply(res, 201, out);
  }

  // Server-Sent Events: the log from Last-Event-ID (or ?after=), then what comes, a heartbeat
  // every 15 s, closed after stream_seconds (EventSource reconnects and resumes by id).
  void stream(const Caller& caller, const Request& req, Response& res) {
    if (streams.fetch_add(1) >= options.streams) {
      streams.fetch_sub(1);
      res.set_header("Retry-After", "5");
      throw Refusal(503, "too many live streams; retry shortly");
    }
    long after = 0;
    const std::string last = req.has_header("Last-Event-ID") ? req.get_header_value("Last-Event-ID") : req.get_param_value("after");
    if (!last.empty()) {
      try {
        after = std::stol(last);
      } catch (...) {
        streams.fetch_sub(1);
        throw Refusal(400, "Last-Event-ID: a number");
      }
    }
    const long project = caller.project;
    const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(options.stream_seconds);
    res.set_header("X-Accel-Buffering", "no");
    res.set_chunked_content_provider(
        "text/event-stream",
        [this, project, after, until, first = true](std::size_t, httplib::DataSink& sink) mutable {
          std::string out;
          if (first) out = "retry: 2000\n\n", first = false;
          for (const Event& e : store.events_after(project, after, 200)) {
            out += "id: " + std::to_string(e.id) + "\nevent: " + e.type + "\ndata: " + e.data.dump() + "\n\n";
            after = e.id;
          }
          if (!out.empty()) return sink.write(out.data(), out.size());
          if (events.stopped() || std::chrono::steady_clock::now() > until || !sink.is_writable()) {
            sink.done();
            return true;
          }
          const double left = std::chrono::duration<double>(until - std::chrono::steady_clock::now()).count();
          const long seen = events.wait(project, after, std::clamp(left, 0.0, 15.0));
          if (seen <= after && !events.stopped()) {
            const std::string beat = ": heartbeat\n\n";
            return sink.write(beat.data(), beat.size());
          }
          return true;
        },
        [this](bool) { streams.fetch_sub(1); });
  }
};

ReviewServer::ReviewServer(ServeOptions options) {
  if (options.mtcs_binary.empty()) options.mtcs_binary = fs::read_symlink("/proc/self/exe");
  options.data = fs::absolute(options.data);  // the checks' links into blobs/ resolve from their own folder
  impl_ = std::make_unique<Impl>(std::move(options));
}

ReviewServer::~ReviewServer() { stop(); }

int ReviewServer::bind() {
  const auto& o = impl_->options;
  if (o.port != 0 && answered(o.bind, o.port))
    throw BindError("cannot listen on " + o.bind + ":" + std::to_string(o.port) + ": another server answers there");
  const int port = o.port == 0 ? impl_->http.bind_to_any_port(o.bind) : (impl_->http.bind_to_port(o.bind, o.port) ? o.port : -1);
  if (port < 0) throw BindError("cannot listen on " + o.bind + ":" + std::to_string(o.port) + " (in use?)");
  return port;
}

void ReviewServer::listen() {
  impl_->listening = true;
  if (!impl_->stop_asked) impl_->http.listen_after_bind();
  impl_->listening = false;
}

// httplib's stop() does nothing until its listen loop runs: asked until listen() has returned.
void ReviewServer::stop() {
  impl_->stop_asked = true;
  impl_->events.stop();
  while (impl_->listening) {
    impl_->http.stop();
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

bool is_loopback(const std::string& address) {
  return address == "::1" || address == "localhost" || address.rfind("127.", 0) == 0;
}

void serve_until_signalled(const ServeOptions& options, std::ostream& out) {
  // The signals go to one thread, which stops the server; every other thread blocks them (the
  // checks' children unblock them again).
  sigset_t stop_signals;
  sigemptyset(&stop_signals);
  sigaddset(&stop_signals, SIGINT);
  sigaddset(&stop_signals, SIGTERM);
  pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);
  ReviewServer server(options);
  const int port = server.bind();
  out << "mtcs serve: listening on http://" << options.bind << ":" << port << " (data "
      << fs::absolute(options.data).string() << ")" << std::endl;
  std::thread waiter([&] {
    int signal = 0;
    sigwait(&stop_signals, &signal);
    server.stop();
  });
  server.listen();
  pthread_kill(waiter.native_handle(), SIGTERM);  // wakes sigwait when the stop came another way
  waiter.join();
  out << "mtcs serve: stopped" << std::endl;
}

void add_user(const fs::path& data, const std::string& name, const std::string& password, Role role) {
  fs::create_directories(data);
  ReviewStore store(data / "serve.sqlite");
  store.add_user(name, hash_password(password), role);
}

}  // namespace mtcs::serve
