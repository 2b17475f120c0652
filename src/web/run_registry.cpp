#include "web/run_registry.hpp"

#include "app/errors.hpp"

namespace sd::web {

std::int64_t RunRegistry::start(std::int64_t owner, Mission mission, ControlSoftware software, std::string text,
                                std::uint64_t seed) {
  std::lock_guard lock(mutex_);
  std::size_t running = 0, running_of_owner = 0;
  for (const auto& [id, run] : runs_) {
    if (run->finished()) continue;
    ++running;
    if (run->owner() == owner) ++running_of_owner;
  }
  if (running_of_owner >= kMaxRunningPerUser)
    throw app::Conflict("you are already simulating " + std::to_string(running_of_owner) +
                        " runs: try again when one has finished");
  if (running >= kMaxRunning)
    throw app::Conflict("the server is already simulating " + std::to_string(running) + " runs: try again in a moment");
  long long kept = LiveRun::robot_ticks(mission);
  for (const auto& [id, run] : runs_) kept += run->robot_ticks();
  while (runs_.size() >= kMaxKept || kept > kMaxKeptRobotTicks) {  // forget the oldest finished run
    auto oldest = runs_.begin();
    while (oldest != runs_.end() && !oldest->second->finished()) ++oldest;
    if (oldest == runs_.end()) break;
    kept -= oldest->second->robot_ticks();
    runs_.erase(oldest);  // a viewer still reading it holds its own reference
  }
  const std::int64_t id = next_id_++;
  runs_.emplace(id, std::make_shared<LiveRun>(owner, std::move(mission), std::move(software), std::move(text), seed));
  return id;
}

std::shared_ptr<const LiveRun> RunRegistry::get(std::int64_t owner, std::int64_t id) const {
  std::lock_guard lock(mutex_);
  const auto it = runs_.find(id);
  if (it == runs_.end() || it->second->owner() != owner) throw app::NotFound("no run " + std::to_string(id));
  return it->second;
}

}  // namespace sd::web
