// mtcs serve: the review server's door: its options and the first account (serve/).
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <cstdio>
#include <iostream>
#include <memory>

#include "mtcs/cli/commands.h"
#include "mtcs/io/input_error.h"
#include "mtcs/serve/review_server.h"

namespace mtcs::cli {

Command add_serve_command(CLI::App& app) {
  struct Options {
    serve::ServeOptions serve;
    std::string data = "mtcs-data", add_user, role = "owner";
    bool insecure_listen = false;
  };
  auto o = std::make_shared<Options>();
  CLI::App* sub = app.add_subcommand(
      "serve",
      "The mold review server: a team uploads meshes, runs the interference check on the server,\n"
      "and marks up what it finds in a browser (review items with comments and viewpoints), each\n"
      "member seeing the others' changes live. One process; everything under --data (an SQLite\n"
      "store and the uploaded files by content hash). It listens on 127.0.0.1; put nginx in front\n"
      "for TLS (docs/serve.md).");
  sub->footer(
      "First run:\n"
      "  echo 'a long passphrase' | mtcs serve --data reviews --add-user anna --role owner\n"
      "  mtcs serve --data reviews --port 8421\n"
      "Roles: viewer (reads), reviewer (+ review items, comments), designer (+ uploads, checks,\n"
      "projects), owner (+ members; a server owner owns every project).\n"
      "Exit codes: 0 stopped (SIGINT or SIGTERM), 2 bad option or address in use.");
  sub->add_option("--data", o->data, "folder of the store and the uploads (created if missing)")->capture_default_str();
  sub->add_option("--port", o->serve.port, "TCP port (0: any free one, printed)")->capture_default_str()->check(CLI::Range(0, 65535));
  sub->add_option("--bind", o->serve.bind, "address to listen on")->capture_default_str();
  sub->add_option("--jobs", o->serve.jobs, "checks run at once")->capture_default_str()->check(CLI::Range(1, 64));
  sub->add_option("--upload-limit", o->serve.upload_bytes, "largest upload, bytes")->capture_default_str();
  sub->add_flag("--insecure-listen", o->insecure_listen, "allow an address other than loopback without TLS in front");
  sub->add_flag("--secure-cookie", o->serve.secure_cookie, "mark the session cookie Secure (behind HTTPS)");
  sub->add_option("--add-user", o->add_user, "create this account (password: one line on standard input) and exit");
  sub->add_option("--role", o->role, "server role of --add-user")->capture_default_str()->check(
      CLI::IsMember({"viewer", "reviewer", "designer", "owner"}));

  return {sub, [o]() -> int {
            o->serve.data = o->data;
            if (!o->add_user.empty()) {
              if (isatty(0)) std::fprintf(stderr, "password: ");
              std::string password;
              std::getline(std::cin, password);
              if (!password.empty() && password.back() == '\r') password.pop_back();
              if (password.size() < 8) throw io::InputError("<stdin>", 1, 0, "password", "at least 8 characters");
              try {
                serve::add_user(o->serve.data, o->add_user, password, *serve::role_from(o->role));
              } catch (const std::invalid_argument& e) {
                throw io::InputError("", 0, 0, "--add-user", e.what());
              }
              std::printf("added %s (%s) to %s\n", o->add_user.c_str(), o->role.c_str(), o->data.c_str());
              return 0;
            }
            if (!serve::is_loopback(o->serve.bind) && !o->insecure_listen)
              throw io::InputError("", 0, 0, "--bind",
                                   o->serve.bind + " is not loopback: serve HTTPS through nginx (docs/serve.md), "
                                                   "or pass --insecure-listen");
            try {
              serve::serve_until_signalled(o->serve, std::cout);
            } catch (const serve::BindError& e) {  // the port or the data folder is taken
              throw io::InputError("", 0, 0, "", e.what());
            }
            return 0;
          }};
}

}  // namespace mtcs::cli
