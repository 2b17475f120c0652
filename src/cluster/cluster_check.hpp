#pragma once
// What a cluster lacks before SwarmDesign can run designs there, as a list a user can act on
// (the `cluster check` command and the web page show it as it is).
#include <string>
#include <vector>

#include "cluster/shell.hpp"

namespace sd::cluster {

struct Check {
  std::string what;    ///< "connection", "sbatch", "squeue", "scancel", "swarmdesign", "working folder", "mpirun"
  bool ok = false;
  std::string detail;  ///< one line: what was found, or what is wrong
};

/// In order: reaching the host (nothing else is checked when that fails); sbatch, squeue and
/// scancel on the path; `binary --version` printing the same first line as
/// `expected_version` (ours; not compared when empty); `workdir` can be created and written;
/// mpirun on the path, which is only reported (ok either way: without it a job runs one process).
std::vector<Check> check_cluster(const Shell& shell, const std::string& binary, const std::string& expected_version,
                                 const std::string& workdir);

}  // namespace sd::cluster
