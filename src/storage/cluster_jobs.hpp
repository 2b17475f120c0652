#pragma once
// The Slurm job behind each design of a cluster project: its id (of the last submission), its
// folder on the cluster, the sbatch settings it was submitted with (a design submitted again
// reuses them), and what Slurm last said of it. The design's own row (designs.hpp) keeps its
// state; this keeps what only a cluster job has.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "storage/projects.hpp"
#include "storage/workspace.hpp"

namespace sd::storage {

struct ClusterJob {
  std::int64_t design_id = 0;
  std::string job_id;     // "" until Slurm accepted a submission
  std::string folder;     // on the cluster
  std::string settings;   // JSON
  std::string slurm_state;
  std::string note;       // the last problem, one line ("" when none)
  std::int64_t submitted_at = 0;
  std::int64_t checked_at = 0;
};

/// An experiment's designs as one Slurm job array.
struct ClusterArrayJob {
  std::int64_t experiment_id = 0;
  std::string job_id;     // "" until Slurm accepted a submission
  std::string folder;     // on the cluster
  std::string settings;   // JSON
  std::vector<std::int64_t> tasks;  // experiment design id of each array task
  std::string slurm_state;
  std::string note;
  std::int64_t submitted_at = 0;
};

class ClusterJobs {
 public:
  /// The jobs of a project obtained through Projects (so already owned by the user).
  ClusterJobs(Workspace& workspace, Project project);

  /// Records a submission of the design (a first one, or again after an interruption); an
  /// empty job id records the job's folder before Slurm has accepted it.
  void submitted(std::int64_t design_id, const std::string& job_id, const std::string& folder, const std::string& settings);
  /// What Slurm (or the way to it) said when it was last asked.
  void observed(std::int64_t design_id, const std::string& slurm_state, const std::string& note);
  std::optional<ClusterJob> find(std::int64_t design_id);

  /// The same for an experiment's job array (its designs' ids by task index).
  void array_submitted(std::int64_t experiment_id, const std::string& job_id, const std::string& folder,
                       const std::string& settings, const std::vector<std::int64_t>& tasks);
  void array_observed(std::int64_t experiment_id, const std::string& slurm_state, const std::string& note);
  std::optional<ClusterArrayJob> find_array(std::int64_t experiment_id);

 private:
  Workspace& workspace_;
  Project project_;
};

}  // namespace sd::storage
