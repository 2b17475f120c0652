#include "app/experiment_backends.hpp"

#include "app/errors.hpp"
#include "app/projects.hpp"
#include "storage/lease.hpp"

namespace sd::app {

LaunchedExperiment launch_experiment(Home& home, const storage::User& user, const ExperimentLaunch& launch,
                                     BackgroundExperiments* server) {
  const storage::Project project = project_or_active(home, user, launch.project);
  LaunchedExperiment out;
  if (project.cluster) {
    out.where = ExperimentWhere::slurm;
    out.slurm = submit_cluster_experiment(home, user, launch.plan, launch.job, project.name, launch.threads);
    out.started.home = home.folder();
    out.started.project = out.slurm->project;
    out.started.experiment = out.slurm->experiment;
    out.started.resumed = out.slurm->designs_done > 0 || out.slurm->still_running;
    out.started.already_finished = out.slurm->experiment.state == storage::DesignState::finished;
    return out;
  }
  if (launch.job.given())
    throw InvalidRequest("--nodes, --ntasks, --cpus-per-task, --time, --partition and --account are for a cluster project; "
                         "this one runs on this machine");
  if (server) {
    out.where = ExperimentWhere::server;
    out.started = server->start(home, user, launch.plan, project.name);
    return out;
  }
  out.where = ExperimentWhere::this_process;
  out.started = start_experiment(home, user, launch.plan, {project.name, storage::owner_text(storage::local_process())});
  return out;
}

std::string stop_experiment(Home& home, const storage::User& user, const std::string& project, const std::string& name,
                            BackgroundExperiments* server) {
  const storage::Project p = project_or_active(home, user, project);
  const storage::Experiment e = storage::Experiments(home.workspace(), p).get(name);
  const auto owner = storage::parse_owner(e.owner);
  if (p.cluster && owner && std::holds_alternative<storage::SlurmJob>(*owner)) return stop_cluster_experiment(home, p, e);
  if (server) return server->stop(home, user, p.name, name);
  BackgroundExperiments here("cli");  // a CLI's stop reaches a CLI process of this machine
  return here.stop(home, user, p.name, name);
}

}  // namespace sd::app
