#pragma once
// CPU seconds of this thread or process (the islands' timing log): work, not wall time, so that
// a rank waiting for the others shows as waiting. Private to src/run.

#include <time.h>

namespace mtcs::run {

inline double cpu_seconds(clockid_t clock) {
  timespec t{};
  ::clock_gettime(clock, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}
inline double process_cpu_seconds() { return cpu_seconds(CLOCK_PROCESS_CPUTIME_ID); }
inline double thread_cpu_seconds() { return cpu_seconds(CLOCK_THREAD_CPUTIME_ID); }

}  // namespace mtcs::run
