#pragma once
// The Exec runs a server holds: each belongs to the user who started it (another user's run is
// "not found"), a bounded number run at once — for each user, so that one user cannot take
// every slot from the others, and for the server — and the oldest finished ones are forgotten.
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "web/live_run.hpp"

namespace sd::web {

class RunRegistry {
 public:
  static constexpr std::size_t kMaxRunning = 16;       // simulations at once, all users together
  static constexpr std::size_t kMaxRunningPerUser = 4;  // simulations at once of one user
  static constexpr std::size_t kMaxKept = 64;     // finished runs kept for late viewers
  // A run keeps its whole timeline (about 35 bytes a robot and tick): this bounds what one run
  // may hold (35 MB), ~40 times the largest catalogue mission; longer runs are the CLI's.
  static constexpr long long kMaxRobotTicks = 1'000'000;
  // All kept timelines together: finished runs are forgotten, oldest first, past this (~300 MB).
  static constexpr long long kMaxKeptRobotTicks = 8'000'000;

  /// Conflict when the user has kMaxRunningPerUser runs still simulating, or the server kMaxRunning.
  std::int64_t start(std::int64_t owner, Mission mission, ControlSoftware software, std::string text,
                     std::uint64_t seed);
  /// The run, if this user started it; NotFound otherwise (the same words either way).
  std::shared_ptr<const LiveRun> get(std::int64_t owner, std::int64_t id) const;

 private:
  mutable std::mutex mutex_;
  std::map<std::int64_t, std::shared_ptr<LiveRun>> runs_;
  std::int64_t next_id_ = 1;
};

}  // namespace sd::web
