#pragma once
// Logs and progress go to stderr through spdlog, the message alone (no time stamp, no level):
// info by default; a command's --quiet keeps warnings and errors only, --verbose adds debug
// lines (the resolved config, the scene's size).

namespace CLI {
class App;
}

namespace mtcs::cli {

// The stderr logger every command writes through (main() calls it first).
void init_log();
// --quiet and --verbose on a subcommand.
void add_log_flags(CLI::App* sub);

}  // namespace mtcs::cli
