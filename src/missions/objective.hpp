#pragma once
// Scoring a run, and the mission's own rules, as ARGoS' loop-function PostStep: after every
// tick (after that tick's physics and control) the mission first applies its rules (the
// Coconut arrest rule may move robots), then its events (TuttiFrutti LED colours, whose
// random choices are drawn at tick 1), then updates its objective. Any sampling draws from
// the run's generator. One tracker serves many runs of one mission: reset() between runs.
#include <variant>

#include "core/rng.hpp"
#include "missions/mission.hpp"
#include "simulator/swarm.hpp"

namespace sd {

class ObjectiveTracker {
 public:
  /// Sizes every buffer for the mission's swarm and duration; `mission` must outlive it.
  explicit ObjectiveTracker(const Mission& mission);

  void reset();
  /// Called after the control step of tick `tick` (1-based, up to mission.ticks).
  void post_step(SwarmState& swarm, int tick, Rng& rng);
  /// The mission's natural value (its direction says whether more is better).
  double value() const;

 private:
  template <class Parameters>
  struct ScoresOf;
  template <class... P>
  struct ScoresOf<std::variant<P...>> {
    using type = std::variant<typename P::Score...>;
  };
  using Score = ScoresOf<ObjectiveParameters>::type;
  static Score make_score(const Mission& mission, const EventTimeline& events);

  const Mission* mission_;
  EventTimeline events_;
  Score score_;  // after events_: a score may read the event ticks
};

}  // namespace sd
