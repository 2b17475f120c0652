#include "app/background_designs.hpp"

#include <iostream>

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

storage::Design BackgroundDesigns::start(const storage::User& user, const std::string& project,
                                  ProjectDesignRequest request) {
  std::lock_guard lock(mutex_);
  reap();
  request.project = project;
  request.owner = storage::owner_text(storage::server_thread(job_ + "-" + std::to_string(next_job_++)));
  Home home(home_);
  request.files = FileScope::own_projects(home, user);  // a server's user names only their own files
  // Refuses a project whose design still runs (here or in another process) before any change.
  auto design = std::make_shared<ProjectDesign>(start_project_design(home, user, request));
  const std::int64_t project_id = design->project.id;
  auto job = std::make_unique<Job>();
  Job* j = job.get();
  j->thread = std::thread([design, j] {
    try {
      run_project_design(*design, {.threads = 0, .evaluator = nullptr, .observer = nullptr, .cancel = &j->cancel});
    } catch (const std::exception& e) {  // recorded as failed by the job; the server goes on
      std::cerr << "design " << design->design.id << " failed: " << e.what() << "\n";
    }
    j->done = true;
  });
  jobs_.emplace(project_id, std::move(job));
  return design->design;
}

bool BackgroundDesigns::stop(std::int64_t project_id) {
  std::lock_guard lock(mutex_);
  const auto it = jobs_.find(project_id);
  if (it == jobs_.end() || it->second->done) return false;
  it->second->cancel.cancel();
  return true;
}

bool BackgroundDesigns::running_here(std::int64_t project_id) const {
  std::lock_guard lock(mutex_);
  const auto it = jobs_.find(project_id);
  return it != jobs_.end() && !it->second->done;
}

}  // namespace sd::app
