#pragma once
// Where an experiment runs, chosen in one place for every front end (as design_backends.hpp
// does for designs): a cluster project's as one Slurm job array (cluster_experiments.hpp), else
// a server's own thread when a server asks (background_experiments.hpp), else this process
// (the caller then runs it: run_experiment). Stopping goes to whoever runs it.
#include <optional>
#include <string>

#include "app/background_experiments.hpp"
#include "app/cluster_experiments.hpp"
#include "app/experiment_job.hpp"
#include "app/slurm_jobs.hpp"

namespace sd::app {

enum class ExperimentWhere { this_process, server, slurm };

/// One request to start (or resume) an experiment, however a front end filled it: the CLI's
/// flags, the web's JSON body, Python's arguments.
struct ExperimentLaunch {
  PlannedExperiment plan;
  std::optional<std::string> project;  // nullopt: the active one
  ClusterJobRequest job{};             // a cluster project's sbatch settings (none: Slurm's defaults)
  unsigned threads = 0;                // assessments of designs that come home
};

struct LaunchedExperiment {
  ExperimentWhere where = ExperimentWhere::this_process;
  StartedExperiment started;                         // project, experiment, resumed, finished
  std::optional<ClusterExperimentSubmission> slurm;  // where == slurm: what was submitted
};

/// Records the experiment (or takes up its interrupted namesake) and starts it where its
/// project's experiments run. InvalidRequest for Slurm settings in a local project.
LaunchedExperiment launch_experiment(Home& home, const storage::User& user, const ExperimentLaunch& launch,
                                     BackgroundExperiments* server = nullptr);

/// Stops experiment `name` of the project through whoever runs it: scancel for its array, its
/// thread's cancel token for this server's, SIGTERM for a CLI process of this machine. Conflict
/// when it does not run or runs out of reach. What was done, in words.
std::string stop_experiment(Home& home, const storage::User& user, const std::string& project, const std::string& name,
                            BackgroundExperiments* server = nullptr);

}  // namespace sd::app
