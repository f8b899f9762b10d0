#include "island_writer.h"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>

#include "cpu_clock.h"

namespace mtcs::run {

IslandWriter::IslandWriter(store::RunStore& db, std::function<void(store::IslandsGeneration&)> complete)
    : db_(db), complete_(std::move(complete)), thread_([this] { loop(); }) {}

IslandWriter::~IslandWriter() {
  {
    const std::lock_guard<std::mutex> lock(mutex_);
    closing_ = true;
  }
  changed_.notify_all();
  thread_.join();
}

void IslandWriter::rethrow_failure() {
  if (failed_) std::rethrow_exception(failed_);
}

void IslandWriter::push(std::vector<store::IslandsGeneration> generations) {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] {
    return failed_ || queued_.empty() || queued_.size() * queued_.front().islands.size() < kMaxQueued;
  });
  rethrow_failure();
  for (auto& g : generations) queued_.push_back(std::move(g));
  lock.unlock();
  changed_.notify_all();
}

void IslandWriter::finish() {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return failed_ || (queued_.empty() && !writing_); });
  rethrow_failure();
}

IslandWriter::Times IslandWriter::times() const {
  const std::lock_guard<std::mutex> lock(mutex_);
  return times_;
}

void IslandWriter::loop() {
  // A little below the islands (nice + 5, this thread only): with as many islands as cores the
  // writer then runs mostly while an island waits at a meeting, rather than taking the core of
  // one the others will wait for. Its bounded queue keeps it from falling behind for long.
  errno = 0;
  const int nice = ::getpriority(PRIO_PROCESS, 0);
  if (errno == 0) ::setpriority(PRIO_PROCESS, id_t(::gettid()), std::min(nice + 5, 19));
  std::unique_lock<std::mutex> lock(mutex_);
  for (;;) {
    changed_.wait(lock, [&] { return closing_ || !queued_.empty(); });
    if (queued_.empty() || failed_) return;  // closing
    std::vector<store::IslandsGeneration> batch;
    batch.swap(queued_);
    writing_ = true;
    lock.unlock();
    changed_.notify_all();  // room in the queue
    const auto t0 = std::chrono::steady_clock::now();
    const double cpu0 = thread_cpu_seconds();
    std::exception_ptr failure;
    try {
      if (complete_)
        for (auto& g : batch) complete_(g);
      db_.save_islands(batch);
    } catch (...) {
      failure = std::current_exception();
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double cpu = thread_cpu_seconds() - cpu0;
    lock.lock();
    times_.wall += wall;
    times_.cpu += cpu;
    ++times_.transactions;
    writing_ = false;
    if (failure) failed_ = failure;
    changed_.notify_all();
    if (failed_) return;
  }
}

}  // namespace mtcs::run
