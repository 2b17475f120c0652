#pragma once
// Scoring a run: an objective is updated after every tick (ARGoS loop-function PostStep)
// and read at the end. Any sampling it needs draws from the run's generator.
#include "core/rng.hpp"
#include "missions/mission.hpp"
#include "simulator/swarm.hpp"

namespace sd {

class ObjectiveTracker {
 public:
  explicit ObjectiveTracker(const ObjectiveSpec& spec) : spec_(&spec) {}

  void reset() { value_ = 0.0; }
  /// Called after the control step of tick `tick` (1-based).
  void post_step(const SwarmState& swarm, int tick, Rng& rng);
  /// The mission's natural value (its direction says whether more is better).
  double value() const { return value_; }

 private:
  const ObjectiveSpec* spec_;
  double value_ = 0.0;
};

}  // namespace sd
