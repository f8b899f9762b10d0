#include "mtcs/run/interruption.h"

#include <atomic>
#include <csignal>
#include <cstddef>

#include <unistd.h>

namespace mtcs::run {

namespace {

// What a signal handler may touch: a lock-free atomic.
std::atomic<int> received{0};
static_assert(std::atomic<int>::is_always_lock_free);

struct sigaction previous_int, previous_term;

// Set while a signal should end the program at once: the text to print (static storage).
std::atomic<const char*> at_once{nullptr};
static_assert(std::atomic<const char*>::is_always_lock_free);

// Only async-signal-safe calls here: write and _exit.
extern "C" void on_signal(int number) {
  if (const char* text = at_once.load()) {
    std::size_t n = 0;
    while (text[n] != 0) ++n;
    [[maybe_unused]] const ssize_t written = ::write(2, text, n);
    ::_exit(128 + number);
  }
  received.store(number);
}

}  // namespace

Interruption::Interruption(const char* before_run) {
  received.store(0);
  at_once.store(before_run);
  struct sigaction action {};
  action.sa_handler = on_signal;
  sigemptyset(&action.sa_mask);
  // Reads and writes in progress go on; the next signal gets the default action (a second
  // Ctrl-C ends the program at once).
  action.sa_flags = SA_RESTART | SA_RESETHAND;
  sigaction(SIGINT, &action, &previous_int);
  sigaction(SIGTERM, &action, &previous_term);
}

void Interruption::begin_run() { at_once.store(nullptr); }

Interruption::~Interruption() {
  at_once.store(nullptr);
  sigaction(SIGINT, &previous_int, nullptr);
  sigaction(SIGTERM, &previous_term, nullptr);
}

int Interruption::signal() const { return received.load(); }

}  // namespace mtcs::run
