#pragma once
// One Exec of the editor: a simulation that runs on its own thread as fast as it computes and
// records its whole timeline as server-sent events (one scene, then frames in batches, then
// the end), so any number of viewers, early or late, read the same events and scrubbing in the
// browser never simulates again. A 1200-tick, 20-robot run is a few hundred kilobytes.
#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "control/control_software.hpp"
#include "missions/mission.hpp"

namespace sd::web {

class LiveRun {
 public:
  /// Starts the run at once on its own thread.
  LiveRun(std::int64_t owner, Mission mission, ControlSoftware software, std::string text, std::uint64_t seed);
  ~LiveRun();  // stops the simulation between two ticks and joins
  LiveRun(const LiveRun&) = delete;
  LiveRun& operator=(const LiveRun&) = delete;

  std::int64_t owner() const { return owner_; }
  /// What a run of `mission` records: robots times frames (the placement and every tick).
  static long long robot_ticks(const Mission& mission) {
    return static_cast<long long>(mission.robots) * (mission.ticks + 1);
  }
  long long robot_ticks() const { return robot_ticks(mission_); }
  bool finished() const;

  /// Waits up to `timeout_ms` for events after the first `from`; appends them to `out` and
  /// returns how many there are now. `done` tells whether the run has ended (no event follows).
  std::size_t wait_events(std::size_t from, std::string& out, int timeout_ms, bool& done) const;

 private:
  void simulate();
  void publish(std::string event, bool last = false);

  const std::int64_t owner_;
  const Mission mission_;
  const ControlSoftware software_;
  const std::string text_;
  const std::uint64_t seed_;

  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  std::vector<std::string> events_;  // whole SSE messages, in order
  bool done_ = false;
  std::atomic<bool> stopping_{false};
  std::thread thread_;
};

}  // namespace sd::web
