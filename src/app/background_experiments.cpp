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

StartedExperiment BackgroundExperiments::start(Home& home, const storage::User& user, const PlannedExperiment& plan,
                                               const std::string& project) {
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
  auto started = std::make_shared<StartedExperiment>(start_experiment(home, user, plan, {project, owner}));
  if (started->already_finished) return *started;
  jobs_.launch(started->experiment.id, user.id, started->project.id, [started](const CancelToken& cancel) {
    try {
      run_experiment(*started, {.threads = 0, .evaluator = nullptr, .observer = nullptr, .cancel = &cancel});
    } catch (const std::exception& e) {  // the experiment stays interrupted; the server goes on
      std::cerr << "experiment " << started->experiment.name << " failed: " << e.what() << "\n";
    }
  });
  return *started;
}

std::string BackgroundExperiments::stop(Home& home, const storage::User& user, const std::string& project,
                                        const std::string& name) {
  storage::Experiments experiments(home.workspace(), storage::Projects(home.workspace(), user).get(project));
  const storage::Experiment e = experiments.get(name);
  if (jobs_.cancel(e.id)) return "asked its thread to stop after the current race step";
  if (e.state != storage::DesignState::running || !storage::owner_alive(e.owner, e.heartbeat_at, storage::unix_now(), 0))
    throw Conflict("experiment " + name + " is not running");
  const auto parsed = storage::parse_owner(e.owner);
  const auto* process = parsed ? std::get_if<storage::LocalProcess>(&*parsed) : nullptr;
  if (!process || !storage::runs_here(*process))
    throw Conflict("experiment " + name + " runs in another server or on another machine: stop it there");
  ::kill(static_cast<pid_t>(process->pid), SIGTERM);  // all it did is durable: it resumes where it was
  for (int i = 0; i < 200 && storage::runs_here(*process); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  return "stopped process " + std::to_string(process->pid);
}

bool BackgroundExperiments::running_here(std::int64_t experiment_id) const { return jobs_.runs(experiment_id); }

}  // namespace sd::app
