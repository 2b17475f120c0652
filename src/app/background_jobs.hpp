#pragma once
// The threads a long-lived process runs jobs on (a server's designs and experiments): each job
// belongs to a user and a group (its project), stops through its CancelToken, and is joined
// once it has ended. The one place that knows how such a thread is started, counted and reaped.
#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

#include "app/cancel_token.hpp"

namespace sd::app {

class BackgroundJobs {
 public:
  BackgroundJobs() = default;
  ~BackgroundJobs();  // cancels every job and waits for it
  BackgroundJobs(const BackgroundJobs&) = delete;
  BackgroundJobs& operator=(const BackgroundJobs&) = delete;

  struct Counts {
    int mine = 0, all = 0;
  };
  /// Jobs still running and not asked to stop (one asked to stop is winding down: it may be
  /// started again at once), the user's and everyone's. Reaps the ended ones.
  Counts running(std::int64_t user_id);
  /// Runs `work` on a thread as job `id`. An ended or stopping job of that id (its row taken up
  /// again the moment it released it) is waited for first: it no longer touches the row.
  void launch(std::int64_t id, std::int64_t user_id, std::int64_t group, std::function<void(const CancelToken&)> work);
  /// Asks job `id` to stop; false when no such job runs here.
  bool cancel(std::int64_t id);
  bool runs(std::int64_t id) const;
  bool runs_in_group(std::int64_t group) const;

 private:
  struct Job {
    std::int64_t user_id = 0, group = 0;
    CancelToken cancel;
    std::atomic<bool> done{false};
    std::thread thread;
  };
  void reap();  // joins the ended jobs (mutex_ held)

  mutable std::mutex mutex_;
  std::map<std::int64_t, std::unique_ptr<Job>> jobs_;
};

}  // namespace sd::app
