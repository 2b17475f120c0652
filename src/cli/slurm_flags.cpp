#include "cli/slurm_flags.hpp"

#include <CLI/CLI.hpp>

namespace sd::cli {

void add_slurm_flags(CLI::App& command, app::ClusterJobRequest& job) {
  auto* slurm = command.add_option_group("Cluster project (Slurm)");
  slurm->add_option("--nodes", job.nodes, "Nodes of each job (sbatch --nodes)");
  slurm->add_option("--ntasks", job.ntasks, "Tasks of each job: one MPI rank each; rank 0 races (sbatch --ntasks)");
  slurm->add_option("--cpus-per-task", job.cpus_per_task, "Threads of each task (sbatch --cpus-per-task; default 1)");
  slurm->add_option("--time", job.time, "Time limit of each job, e.g. 2:00:00 or 1-12 (sbatch --time)");
  slurm->add_option("--partition", job.partition, "Partition (sbatch --partition)");
  slurm->add_option("--account", job.account, "Account charged (sbatch --account)");
}

}  // namespace sd::cli
