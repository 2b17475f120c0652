#pragma once
// Designs of a cluster project, run as Slurm jobs: the jobs behind `run-design`, `status`,
// `stop-design` and `cluster-check` when the project's designs run on a cluster. A design's job
// folder on the cluster holds its mission (the document's text), its sbatch script and, in
// design/, the design folder itself; the job runs `swarmdesign design` there, under mpirun
// when it has several tasks, and resumes from the last checkpoint when submitted again.
// Commands go to the cluster through cluster::Shell: on this machine when it is the login
// node, over the system's ssh otherwise. When a job ends, its design folder comes back into
// the local project, so test-design and the web monitor work on it as on a local design.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>


#include "app/design_backend.hpp"
#include "app/home.hpp"
#include "app/project_design.hpp"
#include "app/slurm_jobs.hpp"
#include "cluster/cluster_check.hpp"
#include "storage/cluster_jobs.hpp"

namespace sd::app {

struct ClusterSubmission {
  storage::Project project;
  storage::Design design;
  storage::ClusterJob job;
  bool resubmitted = false;  // an interrupted design submitted again (it resumes there)
  std::string where;         // "this machine" or "user@host (ssh)"
};

/// Records a design of the active (or named) cluster project and submits its job, or submits
/// its interrupted design again (unless request.fresh). InvalidRequest for a local project or
/// bad settings; Conflict while its design still runs; a cluster::ClusterError (after the
/// design is recorded interrupted, with the error as its note) when the cluster refuses.
ClusterSubmission submit_cluster_design(Home& home, const storage::User& user, const ProjectDesignRequest& request,
                                        const ClusterJobRequest& job);

/// Brings a running cluster design up to date with Slurm: its state and progress, and, once
/// its job has ended, its folder fetched back and how it ended (finished with its best
/// configuration, or interrupted with a one-line note: cancelled, time limit, failure). Never
/// throws for the cluster's sake: an unreachable cluster becomes the job's note and the
/// design keeps its state. The progress of a job still running, read on the cluster.
std::optional<storage::DesignProgress> refresh_cluster_design(Home& home, const storage::Project& project,
                                                              storage::Design& design);

/// The Slurm backend (design_backend.hpp): start submits (submit_cluster_design), refresh asks
/// Slurm (refresh_cluster_design), stop cancels the job (scancel), waits for Slurm to end it and
/// fetches its folder home, so that status shows where the design stopped.
class SlurmJobs final : public DesignBackend {
 public:
  StartedDesign start(Home& home, const storage::User& user, const DesignLaunch& launch) override;
  StoppedDesign stop(Home& home, const storage::Project& project, const storage::Design& design) override;
  std::optional<storage::DesignProgress> refresh(Home& home, const storage::Project& project,
                                                 storage::Design& design) override {
    return refresh_cluster_design(home, project, design);
  }
};

/// What is missing on the cluster side of the active (or named) cluster project.
struct ClusterCheckReport {
  storage::Project project;
  std::string where;
  std::vector<cluster::Check> checks;
  bool ok() const;
};
ClusterCheckReport check_project_cluster(Home& home, const storage::User& user,
                                         const std::optional<std::string>& project = std::nullopt);


}  // namespace sd::app
