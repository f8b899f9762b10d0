// mtcs serve in a build without cpp-httplib and libsodium: the command is listed and says how
// to get it.
#include <CLI/CLI.hpp>

#include "mtcs/cli/commands.h"
#include "mtcs/io/input_error.h"

namespace mtcs::cli {

Command add_serve_command(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("serve", "The mold review server (not in this build: see --help).");
  sub->allow_extras();
  sub->footer("This mtcs was built without the review server. Install its libraries\n"
              "(Debian: apt-get install libcpp-httplib-dev libsodium-dev libpugixml-dev libzip-dev, or scripts/setup.sh) and rebuild.");
  return {sub, [] () -> int {
            throw io::InputError("", 0, 0, "serve",
                                 "this mtcs was built without the review server: apt-get install "
                                 "libcpp-httplib-dev libsodium-dev libpugixml-dev libzip-dev, then rebuild");
          }};
}

}  // namespace mtcs::cli
