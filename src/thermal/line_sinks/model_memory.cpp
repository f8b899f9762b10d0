#include "thermal/line_sinks/model_memory.h"

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace mtcs::thermal {
namespace {

// 87 MB, 1.9 GB.
std::string size_text(double bytes) {
  char text[32];
  if (bytes < 1e9) std::snprintf(text, sizeof text, "%.0f MB", bytes / 1e6);
  else std::snprintf(text, sizeof text, "%.1f GB", bytes / 1e9);
  return text;
}

}  // namespace

std::optional<std::size_t> memory_budget() {
  std::optional<std::size_t> budget;
  const auto least = [&](std::size_t bytes) { budget = budget ? std::min(*budget, bytes) : bytes; };
  std::ifstream meminfo("/proc/meminfo");
  for (std::string line; std::getline(meminfo, line);) {
    std::istringstream in(line);
    std::string key;
    std::size_t kilobytes = 0;
    if (in >> key >> kilobytes && key == "MemAvailable:") least(kilobytes * 1024);
  }
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY) least(std::size_t(limit.rlim_cur));
  if (const char* mb = std::getenv("MTCS_MEMORY_LIMIT"); mb && *mb) {
    char* end = nullptr;
    const double value = std::strtod(mb, &end);
    if (end != mb && *end == '\0' && value > 0) least(std::size_t(value * 1024 * 1024));
  }
  return budget;
}

void check_void_model_memory(std::size_t panels, std::size_t samples) {
  const double bytes = 12 * double(samples) * double(panels);
  const std::optional<std::size_t> budget = memory_budget();
  if (!budget || bytes <= double(*budget)) return;
  throw std::runtime_error("the part's thermal model needs about " + size_text(bytes) + " more for its " +
                           std::to_string(samples) + " samples' potentials (" + std::to_string(panels) +
                           " void panels), more than the " + size_text(double(*budget)) +
                           " this machine has available (or $MTCS_MEMORY_LIMIT allows); a coarser "
                           "thermal.sample_spacing (the samples go with its inverse square), a wider "
                           "thermal.void_panel or fewer points asked for brings it down");
}

}  // namespace mtcs::thermal
