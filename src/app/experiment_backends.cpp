#include "app/experiment_backends.hpp"

#include <signal.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <thread>

#include "app/errors.hpp"
#include "app/quotas.hpp"
#include "app/projects.hpp"
#include "storage/clock.hpp"
#include "storage/lease.hpp"

namespace sd::app {

namespace {

/// The CLI: the experiment is recorded as this process's, and the caller runs it
/// (run_experiment) in the foreground; stopping reaches a CLI process of this machine.
class LocalExperiments final : public ExperimentBackend {
 public:
  LaunchedExperiment start(Home& home, const storage::User& user, const storage::Project& project,
                           const ExperimentLaunch& launch, PlannedExperiment plan) override {
    refuse_cluster_job_settings(launch);
    LaunchedExperiment out;
    out.where = ExperimentWhere::this_process;
    out.started = start_experiment(home, user, plan, {project.name, storage::owner_text(storage::local_process())});
    out.plan = std::move(plan);
    return out;
  }
  std::string stop(Home&, const storage::User&, const storage::Project&, const storage::Experiment& e) override {
    return stop_experiment_process(e);
  }
};

/// A cluster project: the designs still to make go to Slurm as one job array.
class SlurmExperiments final : public ExperimentBackend {
 public:
  LaunchedExperiment start(Home& home, const storage::User& user, const storage::Project& project,
                           const ExperimentLaunch& launch, PlannedExperiment plan) override {
    LaunchedExperiment out;
    out.where = ExperimentWhere::slurm;
    out.slurm = submit_cluster_experiment(home, user, plan, launch.job, project.name, launch.threads);
    out.started.home = home.folder();
    out.started.project = out.slurm->project;
    out.started.experiment = out.slurm->experiment;
    out.started.resumed = out.slurm->designs_done > 0 || out.slurm->still_running;
    out.started.already_finished = out.slurm->experiment.state == storage::DesignState::finished;
    out.plan = std::move(plan);
    return out;
  }
  std::string stop(Home& home, const storage::User&, const storage::Project& project,
                   const storage::Experiment& experiment) override {
    return stop_cluster_experiment(home, project, experiment);
  }
};

LocalExperiments local_experiments;
SlurmExperiments slurm_experiments;

}  // namespace

void refuse_cluster_job_settings(const ExperimentLaunch& launch) {
  if (launch.job.given())
    throw InvalidRequest("--nodes, --ntasks, --cpus-per-task, --time, --partition and --account are for a cluster "
                         "project; this one runs on this machine");
}

std::string stop_experiment_process(const storage::Experiment& e) {
  if (e.state != storage::DesignState::running || !storage::owner_alive(e.owner, e.heartbeat_at, storage::unix_now(), 0))
    throw Conflict("experiment " + e.name + " is not running");
  const auto parsed = storage::parse_owner(e.owner);
  const auto* process = parsed ? std::get_if<storage::LocalProcess>(&*parsed) : nullptr;
  if (!process || !storage::runs_here(*process))
    throw Conflict("experiment " + e.name + " runs in another server or on another machine: stop it there");
  ::kill(static_cast<pid_t>(process->pid), SIGTERM);  // all it did is durable: it resumes where it was
  for (int i = 0; i < 200 && storage::runs_here(*process); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  return "stopped process " + std::to_string(process->pid);
}

ExperimentBackend& experiment_backend_for(const storage::Project& project, ExperimentBackend* server) {
  if (project.cluster) return slurm_experiments;
  return server ? *server : local_experiments;
}

LaunchedExperiment launch_experiment(Home& home, const storage::User& user, const ExperimentLaunch& launch,
                                     ExperimentBackend* server) {
  const storage::Project project = project_or_active(home, user, launch.project);
  PlannedExperiment plan = plan_requested_experiment(launch.protocol, launch.files);
  require_disk_room(home, user);
  // Its whole plan counts when it begins; one of that name exists already: it resumes (or has
  // finished), counting nothing more.
  const bool exists = storage::Experiments(home.workspace(), project).find(plan.protocol.name).has_value();
  RunReservation runs(home, user, exists ? 0 : plan.design_runs + plan.assessment_runs, "this experiment");
  LaunchedExperiment launched = experiment_backend_for(project, server).start(home, user, project, launch, std::move(plan));
  if (!launched.started.resumed) runs.keep();
  return launched;
}

std::string stop_experiment(Home& home, const storage::User& user, const std::string& project, const std::string& name,
                            ExperimentBackend* server) {
  const storage::Project p = project_or_active(home, user, project);
  const storage::Experiment e = storage::Experiments(home.workspace(), p).get(name);
  // Whoever runs it: an array's owner is Slurm even when a server started it.
  const auto owner = storage::parse_owner(e.owner);
  if (p.cluster && owner && std::holds_alternative<storage::SlurmJob>(*owner)) return slurm_experiments.stop(home, user, p, e);
  if (server) return server->stop(home, user, p, e);
  return local_experiments.stop(home, user, p, e);
}

nlohmann::json launched_experiment_document(const LaunchedExperiment& launched, const nlohmann::json& row) {
  const char* where = launched.where == ExperimentWhere::slurm    ? "slurm"
                      : launched.where == ExperimentWhere::server ? "server"
                                                                  : "process";
  return {{"experiment", row},
          {"resumed", launched.started.resumed},
          {"already_finished", launched.started.already_finished},
          {"notes", launched.plan.notes},
          {"where", where}};
}

}  // namespace sd::app
