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

BackgroundExperiments::~BackgroundExperiments() {
  std::lock_guard lock(mutex_);
  for (auto& [id, job] : jobs_) job->cancel.cancel();
  for (auto& [id, job] : jobs_)
    if (job->thread.joinable()) job->thread.join();
}

void BackgroundExperiments::reap() {
  for (auto it = jobs_.begin(); it != jobs_.end();) {
    if (it->second->done) {
      it->second->thread.join();
      it = jobs_.erase(it);
    } else {
      ++it;
    }
  }
}

StartedExperiment BackgroundExperiments::start(Home& home, const storage::User& user, const PlannedExperiment& plan,
                                               const std::string& project) {
  std::lock_guard lock(mutex_);
  reap();
  int mine = 0, all = 0;
  for (const auto& [id, job] : jobs_) {
    if (job->cancel.cancelled()) continue;  // winding down: it may be resumed right away
    ++all;
    mine += job->user_id == user.id ? 1 : 0;
  }
  if (mine >= kPerUser)
    throw Conflict("you have an experiment running on this server, the most one user may: stop it, or run more with "
                   "the CLI (swarmdesign experiment) or on a cluster");
  if (all >= kPerServer)
    throw Conflict("this server runs " + std::to_string(all) + " experiments already, the most it takes: try again "
                   "when one has finished");
  const std::string owner = storage::owner_text(storage::server_thread(job_ + "-" + std::to_string(next_job_++)));
  // Refuses a namesake that still runs (here or elsewhere) or has another protocol.
  auto started = std::make_shared<StartedExperiment>(start_experiment(home, user, plan, {project, owner}));
  if (started->already_finished) return *started;
  // Taken up the moment its stopped thread released it: that thread no longer touches it.
  if (const auto old = jobs_.find(started->experiment.id); old != jobs_.end()) {
    old->second->thread.join();
    jobs_.erase(old);
  }
  auto job = std::make_unique<Job>();
  Job* j = job.get();
  j->user_id = user.id;
  j->thread = std::thread([started, j] {
    try {
      run_experiment(*started, {.threads = 0, .evaluator = nullptr, .observer = nullptr, .cancel = &j->cancel});
    } catch (const std::exception& e) {  // the experiment stays interrupted; the server goes on
      std::cerr << "experiment " << started->experiment.name << " failed: " << e.what() << "\n";
    }
    j->done = true;
  });
  jobs_.emplace(started->experiment.id, std::move(job));
  return *started;
}

std::string BackgroundExperiments::stop(Home& home, const storage::User& user, const std::string& project,
                                        const std::string& name) {
  storage::Experiments experiments(home.workspace(), storage::Projects(home.workspace(), user).get(project));
  const storage::Experiment e = experiments.get(name);
  {
    std::lock_guard lock(mutex_);
    if (const auto it = jobs_.find(e.id); it != jobs_.end() && !it->second->done) {
      it->second->cancel.cancel();
      return "asked its thread to stop after the current race step";
    }
  }
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

bool BackgroundExperiments::running_here(std::int64_t experiment_id) const {
  std::lock_guard lock(mutex_);
  const auto it = jobs_.find(experiment_id);
  return it != jobs_.end() && !it->second->done;
}

}  // namespace sd::app
