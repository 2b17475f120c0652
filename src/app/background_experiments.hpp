#pragma once
// Experiments running in the background of a long-lived process (the web server's "Start
// experiment"): each is the experiment job (experiment_job.hpp) on a thread of its own, leased
// by a storage::ServerThread "<job>-N" of this process and stopped through its CancelToken, so
// it is interrupted and resumes exactly as an experiment of the CLI does. Stopping one that a
// CLI process of this machine runs sends that process SIGTERM (everything it did is durable).
#include <atomic>
#include <cstdint>
#include <mutex>
#include <string>

#include "app/background_jobs.hpp"
#include "app/experiment_backend.hpp"
#include "app/experiment_job.hpp"
#include "app/home.hpp"

namespace sd::app {

class BackgroundExperiments final : public ExperimentBackend {
 public:
  /// Each experiment takes every core: one per user, and a few for the server.
  static constexpr int kPerUser = 1;
  static constexpr int kPerServer = 4;

  explicit BackgroundExperiments(std::string job) : job_(std::move(job)) {}
  // Destroying it cancels every experiment (they become interrupted) and waits for them.

  /// Records the planned experiment in the project (or takes up its interrupted namesake) and
  /// runs it on a thread. Conflict, before anything is recorded, past kPerUser or kPerServer.
  LaunchedExperiment start(Home& home, const storage::User& user, const storage::Project& project,
                           const ExperimentLaunch& launch, PlannedExperiment plan) override;
  /// Asks the experiment to stop after its current race step (a thread of this server) or
  /// stops the CLI process of this machine that runs it. Conflict when it does not run, or
  /// runs elsewhere.
  std::string stop(Home& home, const storage::User& user, const storage::Project& project,
                   const storage::Experiment& experiment) override;
  bool running_here(std::int64_t experiment_id) const;

 private:
  const std::string job_;
  std::mutex start_mutex_;  // counting and starting are one step
  std::atomic<int> next_job_{1};
  BackgroundJobs jobs_;     // by experiment id, grouped by project
};

}  // namespace sd::app
