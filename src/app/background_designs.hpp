#pragma once
// Project designs running in the background of a long-lived process (the web server's "Start"
// and "Stop"): each is the project design job (project_design.hpp) on a thread of its own,
// leased under the owner "<this process>/<job>-N", and stopped through its CancelToken, so it
// is interrupted and resumes exactly as a design of the CLI does.
#include <atomic>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "app/design_job.hpp"
#include "app/project_design.hpp"

namespace sd::app {

class BackgroundDesigns {
 public:
  /// `job` names this process' designs in their leases ("web" -> "web-1", "web-2", ...).
  BackgroundDesigns(std::filesystem::path home, std::string job) : home_(std::move(home)), job_(std::move(job)) {}
  ~BackgroundDesigns();  // cancels every design (they become interrupted) and waits for them

  /// Starts (or resumes) the named project's design; the errors of start_project_design.
  storage::Design start(const storage::User& user, const std::string& project, ProjectDesignRequest request);
  /// Asks the project's design to stop after its current race step; false if this process
  /// does not run it.
  bool stop(std::int64_t project_id);
  bool running_here(std::int64_t project_id) const;

 private:
  struct Job {
    CancelToken cancel;
    std::atomic<bool> done{false};
    std::thread thread;
  };
  void reap();  // joins the finished jobs (mutex_ held)

  const std::filesystem::path home_;
  const std::string job_;
  mutable std::mutex mutex_;
  std::map<std::int64_t, std::unique_ptr<Job>> jobs_;  // by project id
  int next_job_ = 1;
};

}  // namespace sd::app
