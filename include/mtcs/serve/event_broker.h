#pragma once
// Live updates: an event is written to the project's log first (so a page that reconnects
// replays what it missed, by Last-Event-ID, even across a server restart), then every stream
// waiting on the broker wakes and reads the log from where it was.

#include <condition_variable>
#include <map>
#include <mutex>
#include <string>

#include <nlohmann/json.hpp>

#include "mtcs/serve/review_store.h"

namespace mtcs::serve {

class EventBroker {
 public:
  explicit EventBroker(ReviewStore& store) : store_(store) {}
  // Logs and announces; the event's id.
  long publish(long project, const std::string& type, long actor, const nlohmann::json& data);
  // Waits until the project has an event newer than `seen`, the timeout passes or the broker
  // stops; the project's newest event id known to the broker.
  long wait(long project, long seen, double seconds);
  void stop();
  bool stopped();

 private:
  ReviewStore& store_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::map<long, long> latest_;  // per project

  bool stopped_ = false;
};

}  // namespace mtcs::serve
