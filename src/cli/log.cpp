#include "log.h"

#include <CLI/CLI.hpp>
#include <spdlog/sinks/stdout_sinks.h>
#include <spdlog/spdlog.h>

namespace mtcs::cli {

void init_log() {
  if (spdlog::get("mtcs")) return;
  auto logger = spdlog::stderr_logger_st("mtcs");
  logger->set_pattern("%v");
  logger->set_level(spdlog::level::info);
  logger->flush_on(spdlog::level::trace);  // lines appear as they happen, between progress lines
  spdlog::set_default_logger(logger);
}

void add_log_flags(CLI::App* sub) {
  init_log();
  CLI::Option* quiet = sub->add_flag_callback("--quiet", [] { spdlog::set_level(spdlog::level::warn); },
                                              "no progress or log lines (warnings and errors only)");
  CLI::Option* verbose = sub->add_flag_callback("--verbose", [] { spdlog::set_level(spdlog::level::debug); },
                                                "debug lines too: the resolved config, the scene's size");
  quiet->excludes(verbose);
}

}  // namespace mtcs::cli
