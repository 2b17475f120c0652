#pragma once
// TuttiFrutti STOP (its loop function TuttiStLoopFunc): the swarm should move until a signal,
// then stop.
// With tau the tick a mission event fires (a random block lights up) and
// D_i(t) = |p_i(t) - p_i(t-1)| the distance robot i moved during tick t:
//   for t <= tau: F += #{i : D_i(t) <= threshold}   (robots not moving yet)
//   for t >  tau: F += #{i : D_i(t) >  threshold}   (robots still moving)
// Minimise; in [0, N T]. At t = 1 the previous position is the initial one; the robots cannot
// move during tick 1 (ARGoS3 applies a command in the tick after the control step that issued
// it, and none has run yet), so D_i(1) = 0.
#include <string>
#include <vector>

#include "missions/objective_base.hpp"

namespace sd {

class StopThenMoveScore;

struct StopThenMoveObjective {
  using Score = StopThenMoveScore;
  std::string switch_event;  // the name of the mission event that gives tau
  std::size_t event = 0;     // its index, resolved when the mission is read
  double threshold = 0.0005; // m per tick (5 mm/s)
};

/// {"switch_event": "stop", "threshold": 0.0005}
StopThenMoveObjective read_stop_then_move(const Field& f);

class StopThenMoveScore {
 public:
  StopThenMoveScore(const StopThenMoveObjective& params, RunContext run);
  void reset() { value_ = 0.0; }
  void post_step(const SwarmState& swarm, int tick, Rng& rng);
  double value() const { return value_; }

 private:
  const StopThenMoveObjective* params_;
  RunContext run_;
  std::vector<Vec2> previous_;
  double value_ = 0.0;
};

}  // namespace sd
