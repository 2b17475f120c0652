#include "cluster/cluster_check.hpp"

#include <algorithm>
#include <map>

namespace sd::cluster {

namespace {

constexpr int check_timeout_s = 30;

std::string reason(const CommandResult& result) {
  const std::string line = first_line(result.err);
  return line.empty() ? "exit code " + std::to_string(result.exit_code) : line;
}

// "name=/path" lines for each program, "name=" when it is not on the path; one round trip.
std::map<std::string, std::string> find_programs(const Shell& shell) {
  const CommandResult result = shell.run_checked(
      "for p in sbatch squeue scancel mpirun; do printf '%s=' \"$p\"; command -v \"$p\" || echo; done", "", check_timeout_s);
  std::map<std::string, std::string> found;
  std::size_t start = 0;
  while (start < result.out.size()) {
    const std::size_t end = std::min(result.out.find('\n', start), result.out.size());
    const std::string line = result.out.substr(start, end - start);
    if (const std::size_t equals = line.find('='); equals != std::string::npos)
      found[line.substr(0, equals)] = line.substr(equals + 1);
    start = end + 1;
  }
  return found;
}

Check check_binary(const Shell& shell, const std::string& binary, const std::string& expected_version) {
  if (binary.empty()) return {"swarmdesign", false, "no SwarmDesign binary is set for " + shell.describe()};
  const CommandResult result = shell.run_checked(shell_path(binary) + " --version", "", check_timeout_s);
  if (result.exit_code != 0)
    return {"swarmdesign", false, binary + " --version failed on " + shell.describe() + ": " + reason(result)};
  const std::string theirs = first_line(result.out), ours = first_line(expected_version);
  if (!ours.empty() && theirs != ours)
    return {"swarmdesign", false, binary + " on " + shell.describe() + " is '" + theirs + "', this one is '" + ours + "'"};
  return {"swarmdesign", true, binary + ": " + theirs};
}

Check check_workdir(const Shell& shell, const std::string& workdir) {
  if (workdir.empty()) return {"working folder", false, "no working folder is set for " + shell.describe()};
  const std::string probe = shell_path(workdir + "/.swarmdesign-check");
  const CommandResult result = shell.run_checked(
      "mkdir -p " + shell_path(workdir) + " && touch " + probe + " && rm -f " + probe, "", check_timeout_s);
  if (result.exit_code != 0)
    return {"working folder", false, "cannot write in " + workdir + " on " + shell.describe() + ": " + reason(result)};
  return {"working folder", true, workdir + " is writable"};
}

}  // namespace

std::vector<Check> check_cluster(const Shell& shell, const std::string& binary, const std::string& expected_version,
                                 const std::string& workdir) {
  std::vector<Check> checks;
  try {
    const CommandResult reached = shell.run_checked("true", "", check_timeout_s);
    if (reached.exit_code != 0) {
      checks.push_back({"connection", false, "the shell on " + shell.describe() + " fails: " + reason(reached)});
      return checks;
    }
    checks.push_back({"connection", true, shell.local() ? "commands run on this machine" : "ssh to " + shell.target() + " works"});

    std::map<std::string, std::string> programs = find_programs(shell);
    for (const char* slurm_command : {"sbatch", "squeue", "scancel"}) {
      const std::string& where = programs[slurm_command];
      if (where.empty())
        checks.push_back({slurm_command, false, std::string(slurm_command) + " is not on the path of " + shell.describe()});
      else
        checks.push_back({slurm_command, true, where});
    }
    checks.push_back(check_binary(shell, binary, expected_version));
    checks.push_back(check_workdir(shell, workdir));
    const std::string& mpirun = programs["mpirun"];
    checks.push_back({"mpirun", true, mpirun.empty() ? "no mpirun on the path: each job runs one process" : mpirun});
  } catch (const ClusterError& error) {
    // Lost on the way (a timeout, the connection dropped): report it as the failed check.
    checks.push_back({"connection", false, error.what()});
  }
  return checks;
}

}  // namespace sd::cluster
