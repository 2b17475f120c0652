#pragma once
// Where an experiment runs, as design_backend.hpp is for designs: every front end fills one
// ExperimentLaunch (a protocol request and where its files may be read), and the backend of
// the project records the experiment and starts it there:
//   this process  the CLI runs it in the foreground (LocalExperiments, experiment_backends.cpp)
//   a server      the web server's own threads (BackgroundExperiments)
//   Slurm         a cluster project's designs as one job array (SlurmExperiments)
// experiment_backends.hpp chooses; the front ends only ask launch_experiment and stop_experiment.
#include <optional>
#include <string>

#include "app/cluster_experiments.hpp"
#include "app/experiment_job.hpp"
#include "app/home.hpp"
#include "app/protocol_requests.hpp"
#include "app/slurm_jobs.hpp"

namespace sd::app {

enum class ExperimentWhere { this_process, server, slurm };

/// One request to start (or resume) an experiment, however a front end filled it.
struct ExperimentLaunch {
  ProtocolRequest protocol;              // what to run
  std::optional<std::string> project;    // nullopt: the active one
  FileScope files = FileScope::local();  // where its protocol and mission files may be read
  ClusterJobRequest job{};               // a cluster project's sbatch settings (none: Slurm's defaults)
  unsigned threads = 0;                  // assessments of designs that come home
};

struct LaunchedExperiment {
  ExperimentWhere where = ExperimentWhere::this_process;
  PlannedExperiment plan;
  StartedExperiment started;                         // project, experiment, resumed, finished
  std::optional<ClusterExperimentSubmission> slurm;  // where == slurm: what was submitted
};

class ExperimentBackend {
 public:
  virtual ~ExperimentBackend() = default;
  /// Records the planned experiment (or takes up its interrupted namesake) and starts it where
  /// this backend runs experiments.
  virtual LaunchedExperiment start(Home& home, const storage::User& user, const storage::Project& project,
                                   const ExperimentLaunch& launch, PlannedExperiment plan) = 0;
  /// Stops the project's running experiment (it becomes interrupted, resumable); what was
  /// done, in words. Conflict when it does not run or this backend cannot reach it.
  virtual std::string stop(Home& home, const storage::User& user, const storage::Project& project,
                           const storage::Experiment& experiment) = 0;
};

/// InvalidRequest when `launch` carries sbatch settings for a project that runs on this machine
/// (the CLI's and the server's backends refuse them alike).
void refuse_cluster_job_settings(const ExperimentLaunch& launch);

/// SIGTERM to the CLI process of this machine that runs the experiment (all it did is durable:
/// it resumes where it was), once it has ended. Conflict when it does not run, or runs in
/// another server or on another machine.
std::string stop_experiment_process(const storage::Experiment& experiment);

}  // namespace sd::app
