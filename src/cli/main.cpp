// mtcs: designs the cooling bores of permanent molds. This file wires the subcommands.

#include <CLI/CLI.hpp>
#include <iostream>
#include <string>

#include "log.h"
#include "mtcs/cli/commands.h"
#include "mtcs/io/disk_cache.h"
#include "mtcs/io/input_error.h"
#include "mtcs/version.h"
#include "option_error.h"

int main(int argc, char** argv) {
  // The benchmarks are their own program; every argument after "bench" is its.
  if (argc >= 2 && std::string(argv[1]) == "bench") return mtcs::cli::run_bench_program(argc - 2, argv + 2);
  mtcs::cli::init_log();
  CLI::App app{
      "mtcs - cooling-bore design for permanent molds.\n"
      "Exact solid-cylinder distances, mold evaluation and optimisation.\n"
      "Run 'mtcs <command> --help' for a command's options and examples.",
      "mtcs"};
  app.require_subcommand(1);
  // Listed for --help only: main() hands "bench ..." to mtcs-bench before parsing.
  app.add_subcommand("bench", "Benchmarks of the kernels, against peers measured in the same run (runs mtcs-bench;\n"
                              "'mtcs bench --help' lists them).");
  app.set_version_flag("--version", mtcs::kProgram);

  const std::vector<mtcs::cli::Command> commands{
      mtcs::cli::add_optimize_command(app),
      mtcs::cli::add_evaluate_command(app),
      mtcs::cli::add_thermal_command(app),
      mtcs::cli::add_replay_command(app),
      mtcs::cli::add_report_command(app),
      mtcs::cli::add_export_command(app),
      mtcs::cli::add_compare_penalties_command(app),
      mtcs::cli::add_distance_command(app),
      mtcs::cli::add_clearance_command(app),
      mtcs::cli::add_interfere_command(app),
      mtcs::cli::add_access_map_command(app),
      mtcs::cli::add_hypervolume_command(app),
      mtcs::cli::add_serve_command(app),
  };
  // A part's precomputes (its void's panel matrix) are kept between commands, unless --no-cache.
  mtcs::io::set_cache_folder(mtcs::io::default_cache_folder());
  for (const char* name : {"optimize", "evaluate", "thermal", "replay", "report", "compare-penalties"})
    app.get_subcommand(name)->add_flag_callback("--no-cache", [] { mtcs::io::set_cache_folder(std::nullopt); },
                                                "neither read nor keep the part's precomputes (default: kept in "
                                                "$MTCS_CACHE_DIR, else ~/.cache/mtcs)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? 0 : 2;
  }
  std::string running;
  try {
    for (const auto& command : commands) {
      if (!command.app->parsed()) continue;
      running = command.app->get_name();
      return command.run();
    }
  } catch (const mtcs::io::InputError& e) {
    std::cerr << mtcs::cli::describe(e, running) << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "mtcs: error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
