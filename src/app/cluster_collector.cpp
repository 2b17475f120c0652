#include "app/cluster_collector.hpp"

#include <vector>

#include "app/cluster_experiments.hpp"
#include "app/home.hpp"

namespace sd::app {

ClusterCollector::ClusterCollector(std::filesystem::path home, std::chrono::milliseconds interval)
    : home_(std::move(home)), interval_(interval), thread_([this] { run(); }) {}

ClusterCollector::~ClusterCollector() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  thread_.join();
}

void ClusterCollector::follow(const storage::User& user, const std::string& project) {
  std::lock_guard lock(mutex_);
  followed_.insert_or_assign({user.id, project}, user);
}

std::size_t ClusterCollector::followed() const {
  std::lock_guard lock(mutex_);
  return followed_.size();
}

void ClusterCollector::tick() {
  std::lock_guard one(collecting_);
  std::vector<std::pair<std::pair<std::int64_t, std::string>, storage::User>> now;
  {
    std::lock_guard lock(mutex_);
    now.assign(followed_.begin(), followed_.end());
  }
  Home home(home_);  // this thread's own connection
  for (const auto& [key, user] : now) {
    bool running = false;
    try {
      running = collect_cluster_experiments(home, user, key.second).still_running > 0;
    } catch (const std::exception&) {
      // The project was deleted or renamed since, or its database is busy: forgotten; a page
      // that still shows it follows it again.
    }
    if (!running) {
      std::lock_guard lock(mutex_);
      followed_.erase(key);
    }
  }
}

void ClusterCollector::run() {
  std::unique_lock lock(mutex_);
  while (!wake_.wait_for(lock, interval_, [this] { return stopping_; })) {
    lock.unlock();
    tick();
    lock.lock();
  }
}

}  // namespace sd::app
