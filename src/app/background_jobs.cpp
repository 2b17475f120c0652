#include "app/background_jobs.hpp"

namespace sd::app {

BackgroundJobs::~BackgroundJobs() {
  std::lock_guard lock(mutex_);
  for (auto& [id, job] : jobs_) job->cancel.cancel();
  for (auto& [id, job] : jobs_)
    if (job->thread.joinable()) job->thread.join();
}

void BackgroundJobs::reap() {
  for (auto it = jobs_.begin(); it != jobs_.end();) {
    if (it->second->done) {
      it->second->thread.join();
      it = jobs_.erase(it);
    } else {
      ++it;
    }
  }
}

BackgroundJobs::Counts BackgroundJobs::running(std::int64_t user_id) {
  std::lock_guard lock(mutex_);
  reap();
  Counts counts;
  for (const auto& [id, job] : jobs_) {
    if (job->cancel.cancelled()) continue;
    ++counts.all;
    counts.mine += job->user_id == user_id ? 1 : 0;
  }
  return counts;
}

void BackgroundJobs::launch(std::int64_t id, std::int64_t user_id, std::int64_t group,
                            std::function<void(const CancelToken&)> work) {
  std::lock_guard lock(mutex_);
  if (const auto old = jobs_.find(id); old != jobs_.end()) {
    old->second->thread.join();
    jobs_.erase(old);
  }
  auto job = std::make_unique<Job>();
  Job* j = job.get();
  j->user_id = user_id;
  j->group = group;
  j->thread = std::thread([j, work = std::move(work)] {
    work(j->cancel);
    j->done = true;
  });
  jobs_.emplace(id, std::move(job));
}

bool BackgroundJobs::cancel(std::int64_t id) {
  std::lock_guard lock(mutex_);
  const auto it = jobs_.find(id);
  if (it == jobs_.end() || it->second->done) return false;
  it->second->cancel.cancel();
  return true;
}

bool BackgroundJobs::runs(std::int64_t id) const {
  std::lock_guard lock(mutex_);
  const auto it = jobs_.find(id);
  return it != jobs_.end() && !it->second->done;
}

bool BackgroundJobs::runs_in_group(std::int64_t group) const {
  std::lock_guard lock(mutex_);
  for (const auto& [id, job] : jobs_)
    if (job->group == group && !job->done) return true;
  return false;
}

}  // namespace sd::app
