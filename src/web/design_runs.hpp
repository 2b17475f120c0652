#pragma once
// The designs a server runs for its users ("Start" in the design monitor): each is the
// application's project design job (app/project_design.hpp) on a thread of this process,
// leased under the owner "<this process>/web-N", and stopped through its CancelToken, so it
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

namespace sd::web {

class DesignRuns {
 public:
  explicit DesignRuns(std::filesystem::path home) : home_(std::move(home)) {}
  ~DesignRuns();  // cancels every design (they become interrupted) and waits for them

  /// Starts (or resumes) the named project's design; the errors of app::start_project_design.
  storage::Design start(const storage::User& user, const std::string& project, app::ProjectDesignRequest request);
  /// Asks the project's design to stop after its current race step; false if this server
  /// does not run it.
  bool stop(std::int64_t project_id);
  bool running_here(std::int64_t project_id) const;

 private:
  struct Job {
    app::CancelToken cancel;
    std::atomic<bool> done{false};
    std::thread thread;
  };
  void reap();  // joins the finished jobs (mutex_ held)

  const std::filesystem::path home_;
  mutable std::mutex mutex_;
  std::map<std::int64_t, std::unique_ptr<Job>> jobs_;  // by project id
  int next_job_ = 1;
};

}  // namespace sd::web
