#pragma once
// `mtcs serve`: the mold review server of the interference-verification paper. One process: a
// JSON API under /api/v1 (cpp-httplib), the review store (SQLite) and uploaded files under the
// data folder, checks run as child processes, live updates as Server-Sent Events. Every route
// is in one table with the least role it needs; a request that matches no route is 404, and a
// route is answered only after the caller is identified (session cookie + CSRF header, or an
// API token) and holds that role on the project (a project the caller is not a member of is
// 404, never 403: its existence is not told).

#include <cstddef>
#include <filesystem>
#include <memory>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "mtcs/serve/roles.h"

namespace mtcs::serve {

struct ServeOptions {
  std::filesystem::path data = "mtcs-data";
  std::string bind = "127.0.0.1";
  int port = 8421;                    // 0: any free port (tests)
  int jobs = 1;                       // checks at once
  int threads = 16;                   // connections served at once
  int streams = 6;                    // live streams at once (each holds a thread)
  double stream_seconds = 300;        // a live stream's life; the page reconnects by itself
  std::size_t upload_bytes = 64u << 20;
  std::size_t body_bytes = 1u << 20;  // JSON bodies
  std::size_t bcf_bytes = 32u << 20;  // a BCF file to import (snapshots make them large)
  bool secure_cookie = false;         // behind TLS (nginx): the session cookie gets Secure
  std::filesystem::path mtcs_binary;  // what checks run (default: this program)
};

// Who may call a route: anyone, any signed-in user, a user whose server role may create
// projects, or a project member with at least a role.
enum class Access { open, signed_in, creator, member };

struct RouteInfo {
  std::string method, pattern, example;  // example: a path that matches, with project 1
  Access access = Access::open;
  Role least = Role::viewer;  // for Access::member
};

const std::vector<RouteInfo>& route_table();

// The address or port cannot be listened on (in use, no such address).
struct BindError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class ReviewServer {
 public:
  explicit ReviewServer(ServeOptions options);
  ~ReviewServer();
  // Binds to options.bind:options.port; the port bound (BindError when it cannot).
  int bind();
  // Serves until stop() (from another thread or a signal handler's thread).
  void listen();
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// `mtcs serve`: binds, says where it listens on `out` ("mtcs serve: listening on http://ADDR:PORT
// (data DIR)"), serves until SIGINT or SIGTERM. Throws BindError when it cannot listen.
void serve_until_signalled(const ServeOptions& options, std::ostream& out);
bool is_loopback(const std::string& address);

// The first-run step: an account in DATA's store (std::invalid_argument when the name is taken).
void add_user(const std::filesystem::path& data, const std::string& name, const std::string& password, Role role);

}  // namespace mtcs::serve
