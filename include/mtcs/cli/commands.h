#pragma once
// Subcommands of the mtcs binary. Each registers its options on the CLI11 app and returns the
// subcommand with the function that runs it; main() maps exceptions to exit codes
// (InputError -> 2).

#include <functional>
#include <string>

namespace CLI {
class App;
}

namespace mtcs::cli {

struct Command {
  CLI::App* app;
  std::function<int()> run;
};

Command add_distance_command(CLI::App& app);
Command add_evaluate_command(CLI::App& app);
Command add_optimize_command(CLI::App& app);
Command add_hypervolume_command(CLI::App& app);
Command add_replay_command(CLI::App& app);
Command add_compare_penalties_command(CLI::App& app);
Command add_clearance_command(CLI::App& app);
Command add_interfere_command(CLI::App& app);
Command add_thermal_command(CLI::App& app);
Command add_access_map_command(CLI::App& app);
Command add_report_command(CLI::App& app);
Command add_export_command(CLI::App& app);
// The review server; without cpp-httplib and libsodium at build time it says how to get them.
Command add_serve_command(CLI::App& app);

// `mtcs bench ARGS`: runs the mtcs-bench found beside this binary with ARGS (argv without the
// program and "bench"); returns only when it cannot (127: not found).
int run_bench_program(int argc, char** argv);
std::string bench_program_path();

}  // namespace mtcs::cli
