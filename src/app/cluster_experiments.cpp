#include "app/cluster_experiments.hpp"

#include <nlohmann/json.hpp>

#include <map>

#include "app/design_method.hpp"
#include "app/errors.hpp"
#include "app/projects.hpp"
#include "cluster/slurm.hpp"
#include "cluster/transfer.hpp"
#include "experiments/protocol.hpp"
#include "missions/catalogue.hpp"
#include "storage/clock.hpp"
#include "storage/design_store.hpp"
#include "storage/lease.hpp"

namespace sd::app {

namespace {

/// Cluster experiments are owned by their array, whose id lives in cluster_array_jobs.
std::string array_owner(const storage::Project& project) {
  return storage::owner_text(storage::SlurmJob{"array", project.cluster->host});
}

/// Task i makes the design on line i+1 of tasks.txt (its folder, mission file, budget, seed
/// and space), started or resumed from the checkpoint in its folder.
std::string array_body(const std::string& folder, const std::string& binary, const ClusterJobRequest& request) {
  return "set -u\n"
         "cd " + cluster::shell_quote(folder) + " || exit 1\n"
         "set -- $(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" tasks.txt)\n"
         "design=$1 mission=$PWD/$2 budget=$3 seed=$4\n"
         "shift 4\n"
         "mkdir -p \"$design\" && cd \"$design\" || exit 1\n"
         "if [ -f design/design.db ]; then\n"
         "  set -- design --resume \"$PWD/design\"\n"
         "else\n"
         "  set -- design --mission \"$mission\" --budget \"$budget\" --seed \"$seed\" \"$@\" --out \"$PWD/design\"\n"
         "fi\n" +
         design_command_line(binary, request);
}

std::string design_folder_name(std::int64_t id) {
  std::string name = std::to_string(id);
  name.insert(name.begin(), 'd');
  return name;
}

}  // namespace

ClusterExperimentSubmission submit_cluster_experiment(Home& home, const storage::User& user,
                                                      const PlannedExperiment& plan, const ClusterJobRequest& given,
                                                      const std::optional<std::string>& name, unsigned threads) {
  check_request(given);
  for (const auto& d : plan.designs)
    if (const DesignMethod& method = design_method(d.method); !method.runs_on_cluster()) {
      const std::string title(method.info().title);
      throw InvalidRequest("condition " + d.condition + " uses " + title + ", which runs on this machine only; run this "
                           "experiment in a local project, or leave " + title + " out");
    }
  ClusterExperimentSubmission out;
  out.project = project_or_active(home, user, name);
  if (!out.project.cluster) throw std::logic_error("submit_cluster_experiment on a local project");
  const cluster::Shell shell = cluster_shell(out.project);
  out.where = shell.describe();
  storage::Experiments store(home.workspace(), out.project);
  storage::ClusterJobs jobs(home.workspace(), out.project);

  if (const auto existing = store.find(plan.protocol.name); existing && existing->state == storage::DesignState::running) {
    refresh_cluster_experiment(home, out.project, *existing, threads);
    out.experiment = store.get(plan.protocol.name);
    out.still_running = out.experiment.state == storage::DesignState::running;
  }
  if (!out.still_running) {
    auto [experiment, existed] = store.start(plan.protocol.name, experiments::to_json(plan.protocol).dump(), plan.designs,
                                             array_owner(out.project));
    out.experiment = experiment;
  }
  const auto designs = store.designs(out.experiment.id);
  out.designs = static_cast<int>(designs.size());
  if (out.still_running || out.experiment.state == storage::DesignState::finished) {
    for (const auto& d : designs) out.designs_done += d.stage == storage::DesignStage::done ? 1 : 0;
    out.job = jobs.find_array(out.experiment.id);
    return out;
  }

  // What twins already made is taken here; the rest goes to the cluster.
  const auto protocol = experiments::protocol_from_json(nlohmann::json::parse(out.experiment.protocol));
  std::vector<storage::ExperimentDesign> to_make;
  for (auto d : designs) {
    if (d.stage == storage::DesignStage::pending || d.stage == storage::DesignStage::designing) {
      if (const auto twin = store.finished_twin(d)) {
        store.reuse(d.id, twin->first);
        d = store.design(d.id);
        ++out.designs_reused;
      }
    }
    if (d.stage == storage::DesignStage::assessing)
      assess_design(store, d, protocol, {.threads = threads, .evaluator = nullptr, .observer = nullptr, .cancel = nullptr});
    if (d.stage == storage::DesignStage::pending || d.stage == storage::DesignStage::designing) to_make.push_back(d);
    else ++out.designs_done;
  }
  if (to_make.empty()) {
    store.finish(out.experiment.id);
    out.experiment = store.get(plan.protocol.name);
    return out;
  }

  const std::string planned = out.project.cluster->workdir_or_default() + "/" + user.name + "/" + out.project.name +
                              "/experiment-" + out.experiment.name;
  std::vector<std::int64_t> tasks;
  tasks.reserve(tasks.size() + to_make.size());
  for (const auto& d : to_make) tasks.push_back(d.id);
  try {
    jobs.array_submitted(out.experiment.id, "", planned, settings_text(given), tasks);
    const std::string folder = make_cluster_folder(shell, planned);
    // One file per mission, one line per task: a handful of writes, however many designs.
    std::map<std::string, std::string> mission_files;
    std::string lines;
    for (const auto& d : to_make) {
      auto [it, fresh] = mission_files.try_emplace(d.plan.mission, "mission-" + std::to_string(mission_files.size()) + ".json");
      if (fresh) cluster::write_file(shell, folder + "/" + it->second, load_mission(d.plan.mission).document);
      store.set_stage(d.id, storage::DesignStage::designing);
      lines += design_folder_name(d.id) + " " + it->second + " " + std::to_string(d.plan.budget) + " " +
               std::to_string(d.plan.seed) + space_flags(d.plan.architectures, d.plan.flavours) + method_flag(d.plan.method) +
               "\n";
    }
    cluster::write_file(shell, folder + "/tasks.txt", lines);
    const auto settings = job_settings(given, "sd-" + out.project.name + "-" + out.experiment.name, folder, "slurm-%A_%a.out");
    const std::string body = array_body(folder, out.project.cluster->binary_or_default(), given);
    cluster::write_file(shell, folder + "/array.sh",
                        cluster::sbatch_array_script(settings, static_cast<int>(tasks.size()), body), true);
    const std::string job_id = cluster::submit(shell, folder + "/array.sh");
    jobs.array_submitted(out.experiment.id, job_id, folder, settings_text(given), tasks);
  } catch (const cluster::ClusterError& e) {
    store.release(out.experiment.id, out.experiment.owner);
    jobs.array_observed(out.experiment.id, "", e.what());
    throw;
  } catch (...) {
    store.release(out.experiment.id, out.experiment.owner);  // submitted again by the same command
    throw;
  }
  out.designs_submitted = static_cast<int>(tasks.size());
  out.job = jobs.find_array(out.experiment.id);
  return out;
}

void refresh_cluster_experiment(Home& home, const storage::Project& project, const storage::Experiment& experiment,
                                unsigned threads) {
  if (!project.cluster || experiment.state != storage::DesignState::running) return;
  storage::ClusterJobs jobs(home.workspace(), project);
  const auto job = jobs.find_array(experiment.id);
  storage::Experiments store(home.workspace(), project);
  if (!job || job->job_id.empty()) {
    // Its submitting process stopped before Slurm took the array (or is still at it).
    if (job && storage::unix_now() - job->submitted_at < kSubmissionGraceSeconds) return;
    store.release(experiment.id, experiment.owner);
    if (job) jobs.array_observed(experiment.id, "", "its submission did not complete; run the same experiment command again");
    return;
  }
  try {
    const cluster::Shell shell = cluster_shell(project);
    const auto states = cluster::array_status(shell, job->job_id);
    const auto protocol = experiments::protocol_from_json(nlohmann::json::parse(experiment.protocol));
    std::vector<std::string> left;  // designs whose task ended without a result
    bool all_ended = true;
    std::string slurm_state;
    for (std::size_t i = 0; i < job->tasks.size(); ++i) {
      storage::ExperimentDesign d = store.design(job->tasks[i]);
      if (d.stage == storage::DesignStage::done) continue;
      const auto state = states.find(static_cast<int>(i));
      const bool ended = state != states.end() && cluster::finished(state->second.state);
      if (state != states.end() && !cluster::finished(state->second.state)) {
        all_ended = false;
        if (state->second.state == cluster::JobState::running) slurm_state = "RUNNING";
        else if (slurm_state.empty()) slurm_state = state->second.slurm_state;
        continue;
      }
      const std::string there = job->folder + "/" + design_folder_name(d.id);
      if (!cluster::exists(shell, there + "/result.json")) {
        if (ended || state == states.end())
          left.push_back(std::string("#").append(std::to_string(d.plan.replicate)).append(" of ").append(d.plan.condition)
                             .append(" (task ").append(std::to_string(i))
                             .append(ended ? ", " + state->second.slurm_state : std::string(", unknown to Slurm"))
                             .append(")"));
        continue;
      }
      cluster::fetch_folder(shell, there + "/design", d.folder);
      const storage::DesignProgress progress = storage::read_design_progress(d.folder);
      if (!progress.best) continue;
      store.design_finished(d.id, progress.best->command_line, progress.best->mean_score, progress.experiments_used);
      assess_design(store, store.design(d.id), protocol,
                    {.threads = threads, .evaluator = nullptr, .observer = nullptr, .cancel = nullptr});
    }
    if (!all_ended) {
      jobs.array_observed(experiment.id, slurm_state, "");
      return;
    }
    if (left.empty()) {
      store.finish(experiment.id);
      jobs.array_observed(experiment.id, "COMPLETED", "");
      return;
    }
    std::string note = "Slurm array job " + job->job_id + " ended without the design";
    note += left.size() > 1 ? "s " : " ";
    for (std::size_t i = 0; i < left.size(); ++i) {
      if (i > 0) note += ", ";
      note += left[i];
    }
    note += " (logs: " + job->folder + "/slurm-" + job->job_id + "_N.out); run the same experiment command again to "
            "submit them again: they resume from their last checkpoints";
    store.release(experiment.id, experiment.owner);
    jobs.array_observed(experiment.id, "ENDED", note);
  } catch (const cluster::ClusterError& e) {
    jobs.array_observed(experiment.id, "", e.what());
  }
}

std::string stop_cluster_experiment(Home& home, const storage::Project& project, const storage::Experiment& experiment) {
  if (!project.cluster) throw std::logic_error("stop_cluster_experiment in a local project");
  if (experiment.state != storage::DesignState::running) throw Conflict("experiment " + experiment.name + " is not running");
  storage::ClusterJobs jobs(home.workspace(), project);
  const auto job = jobs.find_array(experiment.id);
  if (!job || job->job_id.empty()) throw Conflict("experiment " + experiment.name + " is still being submitted; stop it once Slurm has it");
  cluster::cancel(cluster_shell(project), job->job_id);
  storage::Experiments(home.workspace(), project).release(experiment.id, experiment.owner);
  jobs.array_observed(experiment.id, "CANCELLED",
                      "Slurm array job " + job->job_id + " cancelled; run the same experiment again to resume it");
  return "cancelled Slurm array job " + job->job_id;
}

namespace {
int designs_done(storage::Experiments& store, std::int64_t experiment_id) {
  int done = 0;
  for (const auto& d : store.designs(experiment_id)) done += d.stage == storage::DesignStage::done ? 1 : 0;
  return done;
}
}  // namespace

ClusterCollection collect_cluster_experiments(Home& home, const storage::User& user,
                                              const std::optional<std::string>& project, unsigned threads) {
  ClusterCollection out;
  const storage::Project p = project_or_active(home, user, project);
  if (!p.cluster) return out;
  storage::Experiments store(home.workspace(), p);
  for (const auto& experiment : store.list()) {
    if (experiment.state != storage::DesignState::running) continue;
    ++out.experiments;
    const int done_before = designs_done(store, experiment.id);
    refresh_cluster_experiment(home, p, experiment, threads);
    out.designs_home += designs_done(store, experiment.id) - done_before;
    if (store.get(experiment.name).state == storage::DesignState::running) ++out.still_running;
  }
  return out;
}

}  // namespace sd::app
