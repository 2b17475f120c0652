#pragma once
// Renews a running job's lease (storage/lease.hpp) every kHeartbeatSeconds, on its own
// database connection and thread, until it is stopped: a design, an experiment.
#include <condition_variable>
#include <filesystem>
#include <functional>
#include <mutex>
#include <thread>

#include "app/home.hpp"

namespace sd::app {

class LeaseKeeper {
 public:
  /// `renew` is called with a Home of its own (opened at the first beat and kept).
  LeaseKeeper(std::filesystem::path home, std::function<void(Home&)> renew);
  ~LeaseKeeper() { stop(); }
  LeaseKeeper(const LeaseKeeper&) = delete;
  LeaseKeeper& operator=(const LeaseKeeper&) = delete;

  void stop();

 private:
  void beat(const std::filesystem::path& home, const std::function<void(Home&)>& renew);

  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace sd::app
