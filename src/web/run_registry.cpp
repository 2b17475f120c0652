#include "web/run_registry.hpp"

#include "app/errors.hpp"

namespace sd::web {

long long RunRegistry::UserRuns::robot_ticks() const {
  long long sum = 0;
  for (const auto& [id, run] : runs) sum += run->robot_ticks();
  return sum;
}

bool RunRegistry::UserRuns::has_finished() const {
  for (const auto& [id, run] : runs)
    if (run->finished()) return true;
  return false;
}

bool RunRegistry::UserRuns::forget_oldest() {
  for (auto it = runs.begin(); it != runs.end(); ++it)
    if (it->second->finished()) {
      runs.erase(it);  // a viewer still reading it holds its own reference
      return true;
    }
  return false;
}

long long RunRegistry::kept_robot_ticks() const {
  long long sum = 0;
  for (const auto& [owner, user] : users_) sum += user.robot_ticks();
  return sum;
}

std::int64_t RunRegistry::start(std::int64_t owner, Mission mission, ControlSoftware software, std::string text,
                                std::uint64_t seed) {
  std::lock_guard lock(mutex_);
  std::size_t running = 0, running_of_owner = 0;
  for (const auto& [user_id, user] : users_)
    for (const auto& [id, run] : user.runs) {
      if (run->finished()) continue;
      ++running;
      if (user_id == owner) ++running_of_owner;
    }
  if (running_of_owner >= kMaxRunningPerUser)
    throw app::Conflict("you are already simulating " + std::to_string(running_of_owner) +
                        " runs: try again when one has finished");
  if (running >= kMaxRunning)
    throw app::Conflict("the server is already simulating " + std::to_string(running) + " runs: try again in a moment");

  const long long wanted = LiveRun::robot_ticks(mission);
  UserRuns& mine = users_[owner];
  while ((mine.runs.size() >= limits_.runs_per_user || mine.robot_ticks() + wanted > limits_.robot_ticks_per_user) &&
         mine.forget_oldest()) {
  }
  // The server is full: forget from whoever keeps the most, which is this user only when no one
  // keeps more.
  while (kept_robot_ticks() + wanted > limits_.robot_ticks) {
    UserRuns* heaviest = nullptr;
    long long most = -1;
    for (auto& [user_id, user] : users_)
      if (const long long ticks = user.robot_ticks(); ticks > most && user.has_finished()) {
        most = ticks;
        heaviest = &user;
      }
    if (!heaviest) break;
    heaviest->forget_oldest();
  }
  const std::int64_t id = mine.next_id++;
  mine.runs.emplace(id, std::make_shared<LiveRun>(owner, std::move(mission), std::move(software), std::move(text), seed));
  return id;
}

std::shared_ptr<const LiveRun> RunRegistry::get(std::int64_t owner, std::int64_t id) const {
  std::lock_guard lock(mutex_);
  const auto user = users_.find(owner);
  const auto it = user == users_.end() ? decltype(user->second.runs)::const_iterator() : user->second.runs.find(id);
  if (user == users_.end() || it == user->second.runs.end()) throw app::NotFound("no run " + std::to_string(id));
  return it->second;
}

}  // namespace sd::web
