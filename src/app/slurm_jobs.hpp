#pragma once
// What every Slurm job SwarmDesign submits shares — a cluster project's design
// (cluster_designs) and an experiment's job array (cluster_experiments): the sbatch settings a
// user gives, where the cluster's commands run, the job folder, and the line that makes or
// resumes a design there.
#include <cstdint>
#include <optional>
#include <string>

#include "cluster/shell.hpp"
#include "cluster/slurm.hpp"
#include "storage/projects.hpp"

namespace sd::app {

/// How long a submission may take before a design or experiment still waiting for its job id
/// is taken for one whose submitting process stopped (it then becomes interrupted).
inline constexpr std::int64_t kSubmissionGraceSeconds = 300;

/// The sbatch settings a user may give (empty or nullopt: Slurm's defaults, or those of the
/// last submission).
struct ClusterJobRequest {
  std::optional<int> nodes, ntasks, cpus_per_task;
  std::string time, partition, account;
  bool given() const;
  /// Several tasks: the design runs under mpirun, one rank per task.
  bool on_ranks() const;
};

/// InvalidRequest naming the option Slurm would refuse.
void check_request(const ClusterJobRequest& request);
/// As stored with the job (JSON), and back, with the settings given now taking the place of
/// the stored ones.
std::string settings_text(const ClusterJobRequest& request);
ClusterJobRequest merged(const std::string& stored, const ClusterJobRequest& given);

/// Where the project's cluster commands run: here on its login node, over ssh otherwise.
cluster::Shell cluster_shell(const storage::Project& project);
/// Creates `folder` there (a leading ~/ is that machine's home) and returns its absolute path.
std::string make_cluster_folder(const cluster::Shell& shell, const std::string& folder);

cluster::JobSettings job_settings(const ClusterJobRequest& request, const std::string& job_name,
                                  const std::string& folder, const std::string& output);
/// " --fsm --chocolate": a design space's flags from its stored lists.
std::string space_flags(const std::string& architectures, const std::string& flavours);
/// " --method NAME" for a method other than AutoMoDe's Iterated F-Race; "" for it.
std::string method_flag(const std::string& method);
/// The job script's last line: the design command in "$@" run by `binary` (under mpirun when
/// on ranks), each task on the CPUs Slurm gave it; result.json appears only when it ends.
std::string design_command_line(const std::string& binary, const ClusterJobRequest& request);

}  // namespace sd::app
