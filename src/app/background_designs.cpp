#include "app/background_designs.hpp"

#include <iostream>

#include "app/errors.hpp"
#include "storage/lease.hpp"

namespace sd::app {

BackgroundDesigns::~BackgroundDesigns() {
  std::lock_guard lock(mutex_);
  for (auto& [project, job] : jobs_) job->cancel.cancel();
  for (auto& [project, job] : jobs_)
    if (job->thread.joinable()) job->thread.join();
}

void BackgroundDesigns::reap() {
  for (auto it = jobs_.begin(); it != jobs_.end();) {
    if (it->second->done) {
      it->second->thread.join();
      it = jobs_.erase(it);
    } else {
      ++it;
    }
  }
}

StartedDesign BackgroundDesigns::start(Home& home, const storage::User& user, const DesignLaunch& launch) {
  std::lock_guard lock(mutex_);
  reap();
  // A design asked to stop is winding down (and may be resumed right away): it does not count.
  int mine = 0, all = 0;
  for (const auto& [id, job] : jobs_) {
    if (job->cancel.cancelled()) continue;
    ++all;
    mine += job->user_id == user.id ? 1 : 0;
  }
  if (mine >= kPerUser)
    throw Conflict("you have " + std::to_string(mine) + " designs running on this server, the most one user may: stop one, "
                   "or run more with the CLI (run-design) or on a cluster");
  if (all >= kPerServer)
    throw Conflict("this server runs " + std::to_string(all) + " designs already, the most it takes: try again "
                   "when one has finished");
  ProjectDesignRequest request = launch.design;
  request.owner = storage::owner_text(storage::server_thread(job_ + "-" + std::to_string(next_job_++)));
  request.files = FileScope::own_projects(home, user);  // a server's user names only their own files
  // Refuses a project whose design still runs (here or in another process) before any change.
  auto design = std::make_shared<ProjectDesign>(start_project_design(home, user, request));
  // Resumed the moment its stopped job released it, the design may still have that job's
  // thread winding down (reap left it): it no longer touches the design, so wait for it here
  // rather than lose the new thread to a clash of ids.
  if (const auto old = jobs_.find(design->design.id); old != jobs_.end()) {
    old->second->thread.join();
    jobs_.erase(old);
  }
  auto job = std::make_unique<Job>();
  Job* j = job.get();
  j->project_id = design->project.id;
  j->user_id = user.id;
  j->thread = std::thread([design, j] {
    try {
      run_project_design(*design, {.threads = 0, .evaluator = nullptr, .observer = nullptr, .cancel = &j->cancel});
    } catch (const std::exception& e) {  // recorded as failed by the job; the server goes on
      std::cerr << "design " << design->design.id << " failed: " << e.what() << "\n";
    }
    j->done = true;
  });
  jobs_.emplace(design->design.id, std::move(job));
  return {design->project, design->design, design->resumed, design->abandoned, design->prepared.choice.notes,
          std::nullopt, false, 0, std::nullopt, "this server"};
}

StoppedDesign BackgroundDesigns::stop(Home&, const storage::Project&, const storage::Design& design) {
  std::lock_guard lock(mutex_);
  const auto it = jobs_.find(design.id);
  if (it == jobs_.end() || it->second->done)
    throw Conflict("design " + std::to_string(design.id) + " runs in another process (pid " + std::to_string(design.pid) +
                   "): stop it there");
  it->second->cancel.cancel();
  return {design, "asked its thread to stop after the current race step"};
}

bool BackgroundDesigns::running_here(std::int64_t project_id) const {
  std::lock_guard lock(mutex_);
  for (const auto& [design, job] : jobs_)
    if (job->project_id == project_id && !job->done) return true;
  return false;
}

}  // namespace sd::app
