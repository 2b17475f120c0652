#pragma once
// The Exec runs a server holds: each belongs to the user who started it and is numbered among
// that user's runs (another user's run is "not found", and ids tell nothing of others' work), a
// bounded number run at once — for each user, so that one user cannot take every slot from the
// others, and for the server — and the oldest finished ones are forgotten: a user's own first,
// and when the server is full, those of whoever keeps the most, so that one user's runs never
// push out a lighter user's.
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
  static constexpr std::size_t kMaxKeptPerUser = 32;  // finished runs kept for late viewers, per user
  // A run keeps its whole timeline (about 35 bytes a robot and tick): this bounds what one run
  // may hold (35 MB), ~40 times the largest catalogue mission; longer runs are the CLI's.
  static constexpr long long kMaxRobotTicks = 1'000'000;
  // One user's kept timelines (~140 MB), and all users' together (~300 MB).
  static constexpr long long kMaxKeptRobotTicksPerUser = 4'000'000;
  static constexpr long long kMaxKeptRobotTicks = 8'000'000;

  /// What is kept of finished runs (the defaults above; smaller in tests).
  struct KeptLimits {
    std::size_t runs_per_user = kMaxKeptPerUser;
    long long robot_ticks_per_user = kMaxKeptRobotTicksPerUser;
    long long robot_ticks = kMaxKeptRobotTicks;
  };
  RunRegistry() = default;
  explicit RunRegistry(KeptLimits limits) : limits_(limits) {}

  /// Conflict when the user has kMaxRunningPerUser runs still simulating, or the server kMaxRunning.
  std::int64_t start(std::int64_t owner, Mission mission, ControlSoftware software, std::string text,
                     std::uint64_t seed);
  /// The run, if this user started it; NotFound otherwise (the same words either way).
  std::shared_ptr<const LiveRun> get(std::int64_t owner, std::int64_t id) const;

 private:
  struct UserRuns {
    std::map<std::int64_t, std::shared_ptr<LiveRun>> runs;  // by id, oldest first
    std::int64_t next_id = 1;
    long long robot_ticks() const;
    bool has_finished() const;
    /// Forgets the oldest finished run; false when every run still simulates.
    bool forget_oldest();
  };
  long long kept_robot_ticks() const;

  KeptLimits limits_;
  mutable std::mutex mutex_;
  std::map<std::int64_t, UserRuns> users_;  // by owner
};

}  // namespace sd::web
