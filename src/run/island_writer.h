#pragma once
// Stores an island run's generations from a thread of its own, so that the islands evaluate the
// next generation while the last one is committed (rank 0 would otherwise hold every rank at
// the next collective for the commit). Generations are written in order and whole; when the
// thread fell behind, the waiting ones go in one transaction (still whole generations: a kill
// leaves the store at the last committed one, and a resume continues exactly from there). A
// failed write comes back as the exception of the next push() or of finish().

#include <condition_variable>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "mtcs/store/run_store.h"

namespace mtcs::run {

class IslandWriter {
 public:
  // `complete` fills in what the islands' generations leave to the writer (the archipelago's),
  // in the writer's thread, before they are saved.
  IslandWriter(store::RunStore& db, std::function<void(store::IslandsGeneration&)> complete);
  // Stops the thread after what is queued; an error not reported yet is dropped (the run is
  // ending through another exception then).
  ~IslandWriter();
  IslandWriter(const IslandWriter&) = delete;
  IslandWriter& operator=(const IslandWriter&) = delete;

  // Queues generations (a meeting's, written in one transaction unless more are waiting); waits
  // while kMaxQueued island generations are waiting (a store slower than the islands sets the
  // pace, the memory stays bounded). Throws the error of an earlier write.
  void push(std::vector<store::IslandsGeneration> generations);
  // Returns when every queued generation is committed; throws the error of a write.
  void finish();

  // Time the thread spent in the store's transactions: wall and its own CPU seconds; commits.
  struct Times {
    double wall = 0, cpu = 0;
    long transactions = 0;
  };
  Times times() const;

 private:
  // Island generations (a generation of P islands counts P): room for many meetings of a few
  // islands, so that a writer at its lower priority lags without holding an island up.
  static constexpr std::size_t kMaxQueued = 512;
  void loop();
  void rethrow_failure();

  store::RunStore& db_;
  std::function<void(store::IslandsGeneration&)> complete_;
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<store::IslandsGeneration> queued_;
  bool writing_ = false, closing_ = false;
  std::exception_ptr failed_;
  Times times_;
  std::thread thread_;
};

}  // namespace mtcs::run
