#pragma once
// Checks run on the server. Each job runs the mtcs binary itself as a child process (argv only,
// never a shell; its own process group and folder DATA/jobs/<id>; limits on memory, CPU time
// and file size; killed with the server), so a check that fails or crashes takes nothing else
// down, and cancelling one is a signal. A bounded number run at once (--jobs); the rest wait in
// the store's queue, which outlives the server: at start the jobs a killed server left running
// are marked interrupted, queued ones run. What a check finds is stored as findings, each
// stated against the last check of the same scope (new, persistent, resolved), and every change
// is published to the project's live stream.

#include <atomic>
#include <condition_variable>
#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "mtcs/serve/blob_store.h"
#include "mtcs/serve/event_broker.h"
#include "mtcs/serve/review_store.h"

namespace mtcs::serve {

struct JobLimits {
  double wall_seconds = 600;
  unsigned long memory_bytes = 8UL << 30;
  unsigned long file_bytes = 1UL << 30;
};

class JobRunner {
 public:
  JobRunner(ReviewStore& store, EventBroker& events, const BlobStore& blobs, std::filesystem::path mtcs_binary,
            int workers, JobLimits limits = {});
  ~JobRunner();  // stops the workers; running children are killed and their jobs left interrupted
  JobRunner(const JobRunner&) = delete;
  JobRunner& operator=(const JobRunner&) = delete;

  void wake();  // a job was queued
  // Asks a queued or running job to stop; false when it is neither.
  bool cancel(long job);

 private:
  void work();
  void run(const Job& job);
  // The child's exit code; -1 when it was stopped (cancel, server stopping), -2 past the time limit.
  int run_child(long job, const std::vector<std::string>& argv, const std::filesystem::path& folder);

  ReviewStore& store_;
  EventBroker& events_;
  const BlobStore& blobs_;
  std::filesystem::path binary_;
  JobLimits limits_;
  std::mutex mutex_;
  std::condition_variable queued_;
  std::map<long, bool> cancelled_;  // running jobs: whether a cancel was asked
  bool stopping_ = false, pending_ = false;  // pending_: woken for a new job
  std::vector<std::thread> workers_;
};

// The durable key of an interference between two faces: the components' names and where each
// face is (its centroid on a grid an eighth of the face's size, its area on a quarter-octave
// scale), hashed; equal for the same faces in a re-uploaded or renumbered mesh, different once a
// face moves by more than the grid. Not proof against re-meshing that splits a face: near a grid
// line a re-tessellated face may change its key (then: resolved + new).
std::string interference_key(const std::string& a, const std::string& b, const nlohmann::json& group);

}  // namespace mtcs::serve
