#include "mtcs/run/interruption.h"

#include <atomic>
#include <csignal>

namespace mtcs::run {

namespace {

// What a signal handler may touch: a lock-free atomic.
std::atomic<int> received{0};
static_assert(std::atomic<int>::is_always_lock_free);

struct sigaction previous_int, previous_term;

extern "C" void on_signal(int number) { received.store(number); }

}  // namespace

Interruption::Interruption() {
  received.store(0);
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  // Reads and writes in progress go on; the next signal gets the default action (a second
  // Ctrl-C ends the program at once).
  action.sa_flags = SA_RESTART | SA_RESETHAND;
  sigaction(SIGINT, &action, &previous_int);
  sigaction(SIGTERM, &action, &previous_term);
}

Interruption::~Interruption() {
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
}

int Interruption::signal() const { return received.load(); }

}  // namespace mtcs::run
