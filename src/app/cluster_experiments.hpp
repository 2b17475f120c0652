#pragma once
// Experiments of a cluster project: the designs an experiment still has to make go to Slurm
// as one job array (task i makes design i, in its own folder, resuming it when the array is
// submitted again); each design comes home when its task ends and is assessed here on the
// experiment's fresh seeds (a few runs beside a design's hundred thousand), so the report and
// the web monitor read a cluster experiment like a local one. A design that another experiment
// of the project already made is reused here, as locally, and never submitted.
#include <optional>
#include <string>

#include "app/cluster_designs.hpp"
#include "app/experiment_job.hpp"

namespace sd::app {

struct ClusterExperimentSubmission {
  storage::Project project;
  storage::Experiment experiment;
  std::optional<storage::ClusterArrayJob> job;  // nullopt: nothing left to submit
  int designs = 0, designs_done = 0, designs_submitted = 0, designs_reused = 0;
  bool still_running = false;  // its array runs: nothing was submitted
  std::string where;
};

/// Records the experiment (or takes up the interrupted one of that name), reuses what twins
/// made, and submits the designs still to make as one array. InvalidRequest for an EvoStick
/// condition (it runs on this machine only); a cluster::ClusterError, after recording it as
/// the experiment's note (the experiment is interrupted and can be submitted again), when the
/// cluster refuses.
ClusterExperimentSubmission submit_cluster_experiment(Home& home, const storage::User& user,
                                                      const PlannedExperiment& plan, const ClusterJobRequest& job,
                                                      const std::optional<std::string>& project, unsigned threads);

/// Brings a running cluster experiment up to date with its array: designs whose task ended
/// with a result come home and are assessed; when every task has ended the experiment is
/// finished, or interrupted with a note naming the designs left. Never throws for the
/// cluster's sake: an unreachable cluster becomes the note.
void refresh_cluster_experiment(Home& home, const storage::Project& project, const storage::Experiment& experiment,
                                unsigned threads = 0);

/// Cancels a running cluster experiment's array (scancel): the experiment becomes interrupted
/// and the same experiment resumes it (its designs from their last checkpoints). Conflict when
/// it does not run; a cluster::ClusterError when the cluster refuses.
std::string stop_cluster_experiment(Home& home, const storage::Project& project, const storage::Experiment& experiment);

/// What collect_cluster_experiments did.
struct ClusterCollection {
  int experiments = 0;     // running cluster experiments looked at
  int designs_home = 0;    // designs that came home (and were assessed) in this call
  int still_running = 0;   // experiments whose array still runs
};

/// Collecting, the one step that does work for a cluster experiment after its submission:
/// refreshes every running experiment of the project (refresh_cluster_experiment). Reads
/// (experiments_progress, status, listings) never call it; the commands that want the results
/// (`swarmdesign collect`, `experiment`, `report`) and the web server's ticker do. Nothing to
/// do for a local project.
ClusterCollection collect_cluster_experiments(Home& home, const storage::User& user,
                                              const std::optional<std::string>& project = std::nullopt,
                                              unsigned threads = 0);

}  // namespace sd::app
