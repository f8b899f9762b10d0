#pragma once
// Fault injection for the kill -9 tests (tests/cli/kill_resume_test.cpp): a named place in a run
// where the process may be killed as `kill -9` would kill it. With the environment variable
// MTCS_CRASH_AT=NAME:N the N-th call of crash_point("NAME") raises SIGKILL; without it (every
// run outside those tests) a call costs a getenv. Places: "store-row" (a
// generation's row inserted, not committed), "polish" (after a polish evaluation), "output"
// (an output file written to its temporary, not yet flushed and renamed into place),
// "store-create" (a new store built beside its place, not yet renamed into it).

namespace mtcs::io {

void crash_point(const char* name);

}  // namespace mtcs::io
