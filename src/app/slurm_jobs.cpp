#include "app/slurm_jobs.hpp"

#include <nlohmann/json.hpp>

#include "app/errors.hpp"
#include "core/json_integer.hpp"
#include "design/design_space.hpp"

namespace sd::app {

bool ClusterJobRequest::given() const {
  return nodes || ntasks || cpus_per_task || !time.empty() || !partition.empty() || !account.empty();
}

bool ClusterJobRequest::on_ranks() const { return (ntasks && *ntasks > 1) || (nodes && *nodes > 1); }

void check_request(const ClusterJobRequest& r) {
  for (const auto& [name, value] : {std::pair{"--nodes", r.nodes}, {"--ntasks", r.ntasks}, {"--cpus-per-task", r.cpus_per_task}})
    if (value && *value < 1) throw InvalidRequest(std::string(name) + " must be at least 1");
  require(cluster::time_problem(r.time));
  require(cluster::partition_problem(r.partition));
  require(cluster::account_problem(r.account));
}

std::string settings_text(const ClusterJobRequest& r) {
  nlohmann::json out = nlohmann::json::object();
  if (r.nodes) out["nodes"] = *r.nodes;
  if (r.ntasks) out["ntasks"] = *r.ntasks;
  if (r.cpus_per_task) out["cpus_per_task"] = *r.cpus_per_task;
  if (!r.time.empty()) out["time"] = r.time;
  if (!r.partition.empty()) out["partition"] = r.partition;
  if (!r.account.empty()) out["account"] = r.account;
  return out.dump();
}

ClusterJobRequest merged(const std::string& stored, const ClusterJobRequest& given) {
  ClusterJobRequest r;
  const auto s = stored.empty() ? nlohmann::json::object() : nlohmann::json::parse(stored);
  if (s.contains("nodes")) r.nodes = checked_json_integer<int>(s["nodes"], "cluster settings: nodes");
  if (s.contains("ntasks")) r.ntasks = checked_json_integer<int>(s["ntasks"], "cluster settings: ntasks");
  if (s.contains("cpus_per_task")) r.cpus_per_task = checked_json_integer<int>(s["cpus_per_task"], "cluster settings: cpus_per_task");
  r.time = s.value("time", "");
  r.partition = s.value("partition", "");
  r.account = s.value("account", "");
  if (given.nodes) r.nodes = given.nodes;
  if (given.ntasks) r.ntasks = given.ntasks;
  if (given.cpus_per_task) r.cpus_per_task = given.cpus_per_task;
  if (!given.time.empty()) r.time = given.time;
  if (!given.partition.empty()) r.partition = given.partition;
  if (!given.account.empty()) r.account = given.account;
  return r;
}

cluster::Shell cluster_shell(const storage::Project& project) {
  return cluster::Shell::for_cluster(project.cluster->host, project.cluster->user);
}

std::string make_cluster_folder(const cluster::Shell& shell, const std::string& folder) {
  const std::string q = cluster::shell_path(folder);
  const auto made = shell.run_checked("mkdir -p " + q + " && cd " + q + " && pwd");
  if (made.exit_code != 0)
    throw cluster::ClusterError("cannot create " + folder + " on " + shell.describe() + ": " + cluster::first_line(made.err));
  return cluster::first_line(made.out);
}

cluster::JobSettings job_settings(const ClusterJobRequest& r, const std::string& job_name, const std::string& folder,
                                  const std::string& output) {
  cluster::JobSettings settings;
  settings.job_name = job_name;
  settings.nodes = r.nodes;
  settings.ntasks = r.ntasks;
  settings.cpus_per_task = r.cpus_per_task;
  settings.time = r.time;
  settings.partition = r.partition;
  settings.account = r.account;
  settings.output = folder + "/" + output;  // Slurm expands no ~ here: the folder is absolute
  settings.workdir = folder;
  return settings;
}

std::string method_flag(const std::string& method) { return method == "automode" ? "" : " --method " + method; }

std::string space_flags(const std::string& architectures, const std::string& flavours) {
  std::string out;
  for (const auto& list : {architectures, flavours})
    for (const auto& name : design::split_list(list)) out += " --" + name;
  return out;
}

std::string design_command_line(const std::string& binary, const ClusterJobRequest& request) {
  return (request.on_ranks() ? "mpirun " : "") + cluster::shell_path(binary) +
         " \"$@\" --threads \"${SLURM_CPUS_PER_TASK:-1}\" --json > result.part && mv result.part result.json\n";
}

}  // namespace sd::app
