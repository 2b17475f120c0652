#pragma once
// Slurm from the outside: the batch script we submit, sbatch, and what became of a job.
// The parsers are pure and tested on output copied from Slurm 22.05; the functions taking a
// Shell run the Slurm commands where the cluster is (this machine or over ssh).
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "cluster/error.hpp"
#include "cluster/shell.hpp"

namespace sd::cluster {

struct JobSettings {
  std::string job_name;
  std::optional<int> nodes, ntasks, cpus_per_task;
  std::string time, partition, account;  ///< empty: not given (Slurm's defaults)
  std::string output;                    ///< --output path (may contain %j, %A, %a)
  std::string workdir;                   ///< --chdir
};

/// One-line problem with a Slurm --time value, or "" when fine (empty means "not given").
/// Accepts "M", "M:S", "H:M:S", "D-H", "D-H:M", "D-H:M:S" (digits), "UNLIMITED", "INFINITE".
std::string time_problem(std::string_view time);
/// Letters, digits, '_', '-', '.', not starting with '-' ("" when fine or empty).
std::string partition_problem(std::string_view name);
std::string account_problem(std::string_view name);

/// "#!/bin/bash\n#SBATCH --job-name=..\n..." for the settings given, then `body` verbatim.
/// Values with characters sbatch would split or read as a comment are double-quoted.
/// Throws ClusterError naming the setting for a value Slurm would refuse (bad time,
/// partition or account, a count below 1, a line break in a value).
std::string sbatch_script(const JobSettings& settings, const std::string& body);
/// The same with "#SBATCH --array=0-(count-1)"; count >= 1. Each task reads its index from
/// $SLURM_ARRAY_TASK_ID.
std::string sbatch_array_script(const JobSettings& settings, int count, const std::string& body);

/// "123" from sbatch --parsable output ("123" or "123;cluster", trailing newline);
/// ClusterError quoting the output otherwise.
std::string parse_job_id(const std::string& sbatch_output);

/// Submits a script that already exists on the cluster (`sbatch --parsable PATH`; a leading
/// "~/" is expanded there) and returns the job id. ClusterError: "sbatch refused the job:
/// <sbatch's error line>", "sbatch is not on the path of <describe()>", or unreachable.
std::string submit(const Shell& shell, const std::string& script_path);

enum class JobState { pending, running, completing, completed, failed, cancelled, timeout, node_fail, out_of_memory, preempted, unknown };

std::string to_string(JobState state);  ///< the enumerator's name: "timeout", "node_fail", ...
/// The job will not run any more. `unknown` is not finished: Slurm forgot the job or never
/// knew it, and only the caller can tell which (its output files, the time since submission).
bool finished(JobState state);
/// The state for a Slurm state word, long ("NODE_FAIL") or short ("NF"); unknown when new.
JobState job_state_from_slurm(std::string_view word);

struct JobStatus {
  JobState state = JobState::unknown;
  std::string slurm_state;  ///< Slurm's own word, e.g. "CANCELLED"
  std::string reason;       ///< e.g. "Resources", "TimeLimit", "cancelled by uid 0"; "" for Slurm's "None"
  int exit_code = 0;        ///< the batch script's exit status (ExitCode's first number)
  int signal = 0;           ///< the signal that ended it (ExitCode's second number)
};

/// `squeue -h -j ID -o '%T|%r'`: "RUNNING|None", "PENDING|Resources".
JobStatus parse_squeue_line(const std::string& line);
/// One line of `scontrol show job -o ID`: "JobId=5 ... JobState=TIMEOUT Reason=TimeLimit ... ExitCode=0:15 ...".
JobStatus parse_scontrol_job(const std::string& text);
/// `sacct -n -X -P -j ID -o State,ExitCode`: "CANCELLED by 0|0:15", "COMPLETED|0:0".
JobStatus parse_sacct_line(const std::string& line);

/// Task indexes of an array task list as Slurm prints it: "3", "5_3", "5_[1-3]", "1-3%2",
/// "[0,4-8:2]" (ranges, steps and the "%limit" suffix); empty when it is not one.
std::vector<int> array_task_indexes(std::string_view text);

/// Asks squeue, then scontrol (finished jobs stay there MinJobAge seconds), then sacct
/// (clusters with accounting), in one command. State unknown with reason "Slurm no longer
/// knows job ID" when none knows it. For an array job id: the state of its most active task.
/// Throws ClusterError when the cluster cannot be reached or squeue is not on its path.
JobStatus job_status(const Shell& shell, const std::string& job_id);

/// Every task of array job `job_id` that Slurm knows, by task index (sacct, then scontrol,
/// then squeue -r: the later, more current source wins). Tasks nobody knows are absent.
std::map<int, JobStatus> array_status(const Shell& shell, const std::string& job_id);

/// scancel ID (a job or "ID_N" array task); ClusterError with scancel's error line on failure.
/// Cancelling a job that already ended is not an error.
void cancel(const Shell& shell, const std::string& job_id);

}  // namespace sd::cluster
