#include "mtcs/serve/event_broker.h"

#include <chrono>

namespace mtcs::serve {

long EventBroker::publish(long project, const std::string& type, long actor, const nlohmann::json& data) {
  const long id = store_.add_event(project, type, actor, data);
  {
    std::lock_guard lock(mutex_);
    long& latest = latest_[project];
    if (id > latest) latest = id;
  }
  changed_.notify_all();
  return id;
}

long EventBroker::wait(long project, long seen, double seconds) {
  std::unique_lock lock(mutex_);
  long& latest = latest_[project];
  changed_.wait_for(lock, std::chrono::duration<double>(seconds), [&] { return stopped_ || latest > seen; });
  return latest;
}

void EventBroker::stop() {
  {
    std::lock_guard lock(mutex_);
    stopped_ = true;
  }
  changed_.notify_all();
}

bool EventBroker::stopped() {
  std::lock_guard lock(mutex_);
  return stopped_;
}

}  // namespace mtcs::serve
