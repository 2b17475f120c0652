#include "missions/objective.hpp"

#include <utility>

namespace sd {

ObjectiveTracker::Score ObjectiveTracker::make_score(const Mission& mission, const EventTimeline& events) {
  const RunContext run{mission.robots, mission.ticks, &events};
  return std::visit(
      [&](const auto& parameters) -> Score {
        using Parameters = std::decay_t<decltype(parameters)>;
        return Score(std::in_place_type<typename Parameters::Score>, parameters, run);
      },
      mission.objective.parameters);
}

ObjectiveTracker::ObjectiveTracker(const Mission& mission)
    : mission_(&mission), events_(mission.events, mission.led_arena), score_(make_score(mission, events_)) {}

void ObjectiveTracker::reset() {
  events_.reset();
  std::visit([](auto& score) { score.reset(); }, score_);
}

void ObjectiveTracker::post_step(SwarmState& swarm, int tick, Rng& rng) {
  if (mission_->arrest) apply_arrest_rule(*mission_->arrest, mission_->arena, swarm, rng);
  events_.post_step(swarm, tick, rng);
  std::visit([&](auto& score) { score.post_step(swarm, tick, rng); }, score_);
}

double ObjectiveTracker::value() const {
  return std::visit([](const auto& score) { return score.value(); }, score_);
}

}  // namespace sd
