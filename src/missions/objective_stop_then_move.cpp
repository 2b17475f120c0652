#include "missions/objective_stop_then_move.hpp"

#include "missions/json_field.hpp"
#include "missions/mission_events.hpp"

namespace sd {

StopThenMoveObjective read_stop_then_move(const Field& f) {
  f.only({"type", "direction", "switch_event", "threshold"});
  StopThenMoveObjective o;
  o.switch_event = f.at("switch_event").text();
  o.threshold = f.at("threshold").positive();
  return o;
}

StopThenMoveScore::StopThenMoveScore(const StopThenMoveObjective& params, RunContext run)
    : params_(&params), run_(run), previous_(static_cast<std::size_t>(run.robots)) {}

void StopThenMoveScore::post_step(const SwarmState& swarm, int tick, Rng& /*rng*/) {
  if (tick == 1) previous_.assign(swarm.position.begin(), swarm.position.end());  // same size: no allocation
  const bool before_signal = tick <= run_.events->tick_of(params_->event);
  const double threshold_sq = params_->threshold * params_->threshold;
  int count = 0;
  for (std::size_t i = 0; i < previous_.size(); ++i) {
    const bool moving = (swarm.position[i] - previous_[i]).squared_length() > threshold_sq;
    count += before_signal ? !moving : moving;
    previous_[i] = swarm.position[i];
  }
  value_ += count;
}

}  // namespace sd
