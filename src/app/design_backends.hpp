#pragma once
// The one place that chooses a design's backend (design_backend.hpp): where a project's new
// designs run, which backend can stop a running one (that of its owner, whoever started it),
// and which brings it up to date for `status`.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/design_backend.hpp"

namespace sd::app {

/// Where the project's new designs run: Slurm for a cluster project; else the server's
/// threads when a server asks (`server`), this process otherwise. The one such choice.
DesignBackend& backend_for(const storage::Project& project, DesignBackend* server = nullptr);

/// Starts (or resumes) the active (or launch.design.project's) project's design on its backend.
StartedDesign start_design(Home& home, const storage::User& user, const DesignLaunch& launch,
                           DesignBackend* server = nullptr);

/// Stops the active (or named) project's running design through the backend of its owner:
/// scancel for a Slurm job, SIGTERM to a local process, the cancel token of a server's own
/// thread. Conflict when no design runs, or its owner is out of reach (another server's thread,
/// another machine). Reaching a design means owning its project: the user's projects only.
StoppedDesign stop_design(Home& home, const storage::User& user, const std::optional<std::string>& project = std::nullopt,
                          DesignBackend* server = nullptr);

/// A project's current or last design with what its design.db says: the named project, or the
/// active one (`status`). A running design is first brought up to date by its backend (a
/// cluster project's with Slurm, its progress read on the cluster).
/// How much of a design `status` reads beyond its progress. The race log is the costly part
/// (every configuration of every race, with its mean): a page polling every second leaves it.
enum class StatusDetail {
  progress,     // `status`
  convergence,  // and the best elite per iteration (the page's polls)
  complete,     // and the race log (`status --complete`)
};

struct DesignStatus {
  storage::Project project;
  std::optional<storage::Design> design;
  storage::DesignProgress progress;
  std::vector<storage::RaceRecord> race_log;  // with StatusDetail::complete
  std::vector<storage::ConvergencePoint> convergence;  // from StatusDetail::convergence: the best elite per iteration
  std::optional<storage::ClusterJob> cluster_job;  // a cluster project's design: its Slurm job
};
/// Of the project's latest design, or of design `design_id` (NotFound if the project has none
/// so numbered).
DesignStatus design_status(Home& home, const storage::User& user, StatusDetail detail,
                           const std::optional<std::string>& project = std::nullopt,
                           std::optional<std::int64_t> design_id = std::nullopt);

/// The same for the design an experiment of the project is making (or stopped in), or for its
/// design `design_id` (made, being made, or waiting; NotFound before it starts): its race read
/// from its folder. NotFound when the experiment has none under way (all done) or no such design.
DesignStatus experiment_design_status(Home& home, const storage::User& user, const std::string& project,
                                      const std::string& experiment, StatusDetail detail,
                                      std::optional<std::int64_t> design_id = std::nullopt);

}  // namespace sd::app
