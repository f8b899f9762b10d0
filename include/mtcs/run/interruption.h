#pragma once
// Ctrl-C (SIGINT) or SIGTERM during a long run: the first signal asks the run to stop at the end
// of the generation it is computing, so that the best-so-far results can be written and the run
// resumed; a second one ends the program at once (the run store still holds every generation
// stored so far).

namespace mtcs::run {

class Interruption {
 public:
  // Catches SIGINT and SIGTERM while it lives; the previous handlers come back after. With
  // `before_run`, a signal before begin_run() ends the program at once (exit 128 + the signal)
  // after printing that text: a model build of many seconds has nothing to save, and the user
  // should not wait for it (only whole files are ever written: the cache's by rename).
  explicit Interruption(const char* before_run = nullptr);
  ~Interruption();
  Interruption(const Interruption&) = delete;
  Interruption& operator=(const Interruption&) = delete;

  // From here on a signal asks the run to stop after its generation.
  void begin_run();
  // The signal received (SIGINT or SIGTERM), 0 while none has come.
  int signal() const;
  bool requested() const { return signal() != 0; }
  // The exit status a shell expects of a program ended by that signal: 128 + its number.
  int exit_code() const { return 128 + signal(); }
};

}  // namespace mtcs::run
