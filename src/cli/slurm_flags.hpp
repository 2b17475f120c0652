#pragma once
// The sbatch options a cluster project's run-design and experiment accept, in one place.
#include "app/cluster_designs.hpp"

namespace CLI {
class App;
}

namespace sd::cli {

/// --nodes, --ntasks, --cpus-per-task, --time, --partition, --account, as one option group.
void add_slurm_flags(CLI::App& command, app::ClusterJobRequest& job);

}  // namespace sd::cli
