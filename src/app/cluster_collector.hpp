#pragma once
// The web server's one ticker for cluster experiments: a page that shows a project's
// experiments only reads them (experiments_progress starts no work), and asks this collector to
// follow the project; every `interval` the collector's own thread collects each followed
// project (collect_cluster_experiments: designs come home and are assessed) and forgets those
// with nothing left running. So a poll answers at once, and collecting runs once per project
// however many pages poll it.
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <utility>

#include "storage/accounts.hpp"

namespace sd::app {

class ClusterCollector {
 public:
  ClusterCollector(std::filesystem::path home, std::chrono::milliseconds interval);
  ~ClusterCollector();  // stops the ticker (a collection under way ends first)
  ClusterCollector(const ClusterCollector&) = delete;
  ClusterCollector& operator=(const ClusterCollector&) = delete;

  /// The user's project has a running experiment: collect it from the next tick on. No work here.
  void follow(const storage::User& user, const std::string& project);
  std::size_t followed() const;
  /// One collection of every followed project now, on the caller's thread (what the ticker does).
  void tick();

 private:
  void run();

  const std::filesystem::path home_;
  const std::chrono::milliseconds interval_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::mutex collecting_;  // one collection at a time (ticker or tick())
  std::map<std::pair<std::int64_t, std::string>, storage::User> followed_;  // by (user id, project)
  std::thread thread_;     // last: started once the rest exists
};

}  // namespace sd::app
