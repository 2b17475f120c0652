#include "app/design_backends.hpp"

#include "app/cluster_designs.hpp"
#include "app/errors.hpp"
#include "app/experiment_job.hpp"
#include "app/local_processes.hpp"
#include "app/project_design.hpp"
#include "app/projects.hpp"
#include "app/quotas.hpp"
#include "storage/design_store.hpp"
#include "storage/lease.hpp"

namespace sd::app {

namespace {

LocalProcesses local_processes;
SlurmJobs slurm_jobs;

/// Who can stop a running design: the backend of its owner, whichever started it.
DesignBackend& stopper_of(const storage::Design& design, DesignBackend* server) {
  const auto owner = storage::parse_owner(design.owner);
  if (owner && std::holds_alternative<storage::SlurmJob>(*owner)) return slurm_jobs;
  if (owner && std::holds_alternative<storage::ServerThread>(*owner) && server) return *server;
  return local_processes;  // a CLI process; it refuses what it cannot reach
}

/// The race as far as it went, from the design's own folder.
void read_race(DesignStatus& status, StatusDetail detail) {
  const storage::Design& d = *status.design;
  try {
    if (std::filesystem::exists(storage::DesignStore::file_in(d.folder))) {
      status.progress = storage::read_design_progress(d.folder);
      if (detail != StatusDetail::progress) status.convergence = storage::read_convergence(d.folder);
      if (detail == StatusDetail::complete) status.race_log = storage::read_race_log(d.folder);
    }
  } catch (const storage::DesignFolderError&) {
    // A design that has just started may not have committed its tables yet.
    if (d.state != storage::DesignState::running) throw;
  }
}

}  // namespace

DesignBackend& backend_for(const storage::Project& project, DesignBackend* server) {
  if (project.cluster) return slurm_jobs;
  return server ? *server : local_processes;
}

StartedDesign start_design(Home& home, const storage::User& user, const DesignLaunch& launch, DesignBackend* server) {
  const storage::Project project = project_or_active(home, user, launch.design.project);
  require_disk_room(home, user);
  // A new design counts its budget once started; an interrupted one that resumes counted its
  // runs when it began (and a start that resumes after all counts nothing below).
  const bool resumed = resumes(storage::Designs(home.workspace(), project).latest(), launch.design.fresh);
  RunReservation runs(home, user, resumed ? 0 : project.budget.value_or(0), "this design");
  StartedDesign started = backend_for(project, server).start(home, user, launch);
  if (!started.resumed) runs.keep();
  return started;
}

StoppedDesign stop_design(Home& home, const storage::User& user, const std::optional<std::string>& name,
                          DesignBackend* server) {
  const storage::Project project = project_or_active(home, user, name);
  storage::Designs designs(home.workspace(), project);
  auto latest = designs.latest();
  if (latest) backend_for(project, server).refresh(home, project, *latest);
  if (!latest || latest->state != storage::DesignState::running)
    throw Conflict("no design of " + project.name + " is running");
  StoppedDesign out = stopper_of(*latest, server).stop(home, project, *latest);
  out.design = *designs.latest();  // a local design whose process is gone is found interrupted here
  return out;
}

DesignStatus design_status(Home& home, const storage::User& user, StatusDetail detail,
                           const std::optional<std::string>& project, std::optional<std::int64_t> design_id) {
  DesignStatus status;
  storage::Projects projects(home.workspace(), user);
  status.project = project ? projects.get(*project) : projects.require_active();
  storage::Designs designs(home.workspace(), status.project);
  if (design_id) {
    for (auto& design : designs.list())
      if (design.id == *design_id) status.design = std::move(design);
    if (!status.design) designs.get(*design_id);  // throws its NotFound
  } else {
    status.design = designs.latest();
  }
  if (!status.design) return status;
  std::optional<storage::DesignProgress> on_cluster;
  if (status.project.cluster) {
    on_cluster = backend_for(status.project).refresh(home, status.project, *status.design);
    status.cluster_job = storage::ClusterJobs(home.workspace(), status.project).find(status.design->id);
  }
  if (on_cluster) {
    status.progress = *on_cluster;
    return status;
  }
  read_race(status, detail);
  return status;
}

namespace {

/// An experiment's design as /status shows a design: a row made from its plan, its race read
/// from its folder.
DesignStatus experiment_design(const storage::Project& project, const storage::Experiment& experiment,
                               const storage::ExperimentDesign& x, StatusDetail detail) {
  DesignStatus status;
  status.project = project;
  storage::Design d;
  d.id = x.id;
  d.architectures = x.plan.architectures;
  d.flavours = x.plan.flavours;
  d.method = x.plan.method;
  d.mission = x.plan.mission;
  d.budget = x.plan.budget;
  d.seed = x.plan.seed;
  d.folder = x.folder;
  d.best_config = x.configuration;
  d.best_score = x.design_score;
  // Made once it is being assessed; running while its experiment runs and it is being designed;
  // otherwise it waits for its experiment to resume.
  if (x.stage == storage::DesignStage::assessing || x.stage == storage::DesignStage::done)
    d.state = storage::DesignState::finished;
  else if (experiment.state == storage::DesignState::running && x.stage == storage::DesignStage::designing)
    d.state = storage::DesignState::running;
  else
    d.state = storage::DesignState::interrupted;
  status.design = d;
  read_race(status, detail);
  return status;
}

}  // namespace

DesignStatus experiment_design_status(Home& home, const storage::User& user, const std::string& project,
                                      const std::string& experiment, StatusDetail detail,
                                      std::optional<std::int64_t> design_id) {
  const storage::Project p = storage::Projects(home.workspace(), user).get(project);
  if (design_id) {
    storage::Experiments experiments(home.workspace(), p);
    const storage::Experiment e = experiments.get(experiment);  // NotFound naming the ones it has
    for (const storage::ExperimentDesign& x : experiments.designs(e.id)) {
      if (x.id != *design_id) continue;
      if (x.stage == storage::DesignStage::pending)
        throw NotFound("design " + std::to_string(x.id) + " of experiment " + experiment + " has not started yet");
      storage::ExperimentDesign shown = x;
      if (x.reused_from) shown.folder = experiments.design(*x.reused_from).folder;  // its twin's race
      return experiment_design(p, e, shown, detail);
    }
    throw NotFound("experiment " + experiment + " has no design " + std::to_string(*design_id));
  }
  for (const ExperimentProgress& e : experiments_progress(home, user, project)) {
    if (e.experiment.name != experiment) continue;
    if (!e.current) throw NotFound("experiment " + experiment + " has no design under way: all are done");
    return experiment_design(p, e.experiment, *e.current, detail);
  }
  storage::Experiments(home.workspace(), p).get(experiment);  // NotFound naming the ones it has
  throw NotFound("no experiment " + experiment);
}

}  // namespace sd::app
