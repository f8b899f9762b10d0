#include "mtcs/io/crash_point.h"

#include <atomic>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <string>

namespace mtcs::io {
namespace {

struct Plan {
  std::string name;  // empty: no crash planned
  long at = 0;
};

Plan read_plan() {
  const char* env = std::getenv("MTCS_CRASH_AT");
  if (!env) return {};
  const char* colon = std::strrchr(env, ':');
  if (!colon) return {};
  return {std::string(env, colon), std::atol(colon + 1)};
}

}  // namespace

void crash_point(const char* name) {
  static const Plan plan = read_plan();
  if (plan.name.empty() || plan.name != name) return;
  static std::atomic<long> calls{0};
  if (++calls == plan.at) std::raise(SIGKILL);
}

}  // namespace mtcs::io
