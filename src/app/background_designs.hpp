#pragma once
// Project designs running in the background of a long-lived process (the web server's "Start"
// and "Stop"), the server-thread backend (design_backend.hpp): each is the project design job
// (project_design.hpp) on a thread of its own, leased by a storage::ServerThread "<job>-N" of
// this process, and stopped through its CancelToken, so it is interrupted and resumes exactly
// as a design of the CLI does.
#include <atomic>
#include <cstdint>
#include <mutex>
#include <string>

#include "app/background_jobs.hpp"
#include "app/design_backend.hpp"
#include "app/design_job.hpp"
#include "app/project_design.hpp"

namespace sd::app {

class BackgroundDesigns final : public DesignBackend {
 public:
  /// Designs one user may run here at once, and all users together: each takes every core, so
  /// more only share them, and one user cannot take the server's threads from the others.
  static constexpr int kPerUser = 2;
  static constexpr int kPerServer = 8;

  /// `job` names this process' designs in their leases ("web" -> "web-1", "web-2", ...).
  explicit BackgroundDesigns(std::string job) : job_(std::move(job)) {}
  // Destroying it cancels every design (they become interrupted) and waits for them.

  /// Starts (or resumes) launch.design.project's design on a thread; the errors of
  /// start_project_design. Its files may only be the user's own (FileScope::own_projects).
  /// Conflict, before anything changes, past kPerUser or kPerServer designs running here.
  StartedDesign start(Home& home, const storage::User& user, const DesignLaunch& launch) override;
  /// Asks the design to stop after its current race step (it is still running when this
  /// returns). Conflict when it runs on a thread of another process.
  StoppedDesign stop(Home& home, const storage::Project& project, const storage::Design& design) override;
  std::optional<storage::DesignProgress> refresh(Home&, const storage::Project&, storage::Design&) override {
    return std::nullopt;
  }
  bool running_here(std::int64_t project_id) const;

 private:
  const std::string job_;
  std::mutex start_mutex_;  // counting and starting are one step
  std::atomic<int> next_job_{1};
  BackgroundJobs jobs_;     // by design id, grouped by project
};

}  // namespace sd::app
