#include "app/background_experiments.hpp"

#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <iostream>
#include <variant>

#include "app/errors.hpp"
#include "storage/clock.hpp"
#include "storage/lease.hpp"

namespace sd::app {

LaunchedExperiment BackgroundExperiments::start(Home& home, const storage::User& user, const storage::Project& project,
                                                const ExperimentLaunch& launch, PlannedExperiment plan) {
  refuse_cluster_job_settings(launch);
  std::lock_guard lock(start_mutex_);
  const BackgroundJobs::Counts running = jobs_.running(user.id);
  if (running.mine >= kPerUser)
    throw Conflict("you have an experiment running on this server, the most one user may: stop it, or run more with "
                   "the CLI (swarmdesign experiment) or on a cluster");
  if (running.all >= kPerServer)
    throw Conflict("this server runs " + std::to_string(running.all) + " experiments already, the most it takes: try "
                   "again when one has finished");
  const std::string owner = storage::owner_text(storage::server_thread(job_ + "-" + std::to_string(next_job_++)));
  // Refuses a namesake that still runs (here or elsewhere) or has another protocol.
  auto started = std::make_shared<StartedExperiment>(start_experiment(home, user, plan, {project.name, owner}));
  LaunchedExperiment out;
  out.where = ExperimentWhere::server;
  out.started = *started;
  out.plan = std::move(plan);
  if (started->already_finished) return out;
  const unsigned threads = launch.threads;  // 0: the server's pool, all cores
  jobs_.launch(started->experiment.id, user.id, started->project.id, [started, threads](const CancelToken& cancel) {
    try {
      run_experiment(*started, {.threads = threads, .evaluator = nullptr, .observer = nullptr, .cancel = &cancel});
    } catch (const std::exception& e) {  // the experiment stays interrupted; the server goes on
      std::cerr << "experiment " << started->experiment.name << " failed: " << e.what() << "\n";
    }
  });
  return out;
}

std::string BackgroundExperiments::stop(Home&, const storage::User&, const storage::Project&,
                                        const storage::Experiment& experiment) {
  if (jobs_.cancel(experiment.id)) return "asked its thread to stop after the current race step";
  return stop_experiment_process(experiment);  // a CLI process of this machine, if it is one
}

bool BackgroundExperiments::running_here(std::int64_t experiment_id) const { return jobs_.runs(experiment_id); }

}  // namespace sd::app
