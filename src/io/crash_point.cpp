#include "mtcs/io/crash_point.h"

#include <atomic>
#include <csignal>
#include <cstdlib>
#include <cstring>

namespace mtcs::io {

void crash_point(const char* name) {
  // Read at every call, not once: a test's forked child sets it after its parent has passed
  // crash points. Every place is next to far heavier work (a row's insert, an evaluation, a file).
  const char* plan = std::getenv("MTCS_CRASH_AT");
  if (!plan) return;
  const char* colon = std::strrchr(plan, ':');
  const std::size_t length = std::strlen(name);
  if (!colon || std::size_t(colon - plan) != length || std::strncmp(plan, name, length) != 0) return;
  static std::atomic<long> calls{0};
  if (++calls == std::atol(colon + 1)) std::raise(SIGKILL);
}

}  // namespace mtcs::io
