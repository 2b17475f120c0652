#pragma once
// Mission events: things the arena does at a given tick, such as TuttiFrutti's LED colours (its
// loop functions TuttiAg/St/FrLoopFunc): colours switched on at clock 1 (AGGREGATION,
// FORAGING), or one random block lit at a random stop time tau ~ U{400..600} (STOP). Like the
// loop functions, every random choice is drawn at tick 1, event after event, in file order
// (tick, then side, then block), from the run's generator; an event then fires in the PostStep
// of its tick, so the robots' camera sees it from the next tick on.
#include <cstdint>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "missions/led_arena.hpp"
#include "simulator/swarm.hpp"

namespace sd {

class Field;

struct MissionEvent {
  /// Side or block selectors: a 1-based number, or one of these.
  static constexpr int kEvery = 0;
  static constexpr int kRandom = -1;
  struct LedChange {
    int side = kEvery;
    int block = kEvery;
    std::uint32_t color = 0;  // 0 = off
  };
  std::string name;
  int first_tick = 1, last_tick = 1;  // the tick is uniform in [first, last]
  std::vector<LedChange> leds;
};

/// {"name": "stop", "tick": 1 | {"uniform": [400, 600]},
///  "set_leds": [{"side": k | "every" | "random", "block": j | "every" | "random", "color": C}, ...]}
MissionEvent read_mission_event(const Field& f, const LedArena& led_arena, int mission_ticks);

/// The events of one run: when each fires and which blocks it changes.
class EventTimeline {
 public:
  EventTimeline(const std::vector<MissionEvent>& events, const LedArena& led_arena);
  void reset();
  /// At tick 1 draws the random choices; at every tick applies the events due.
  void post_step(SwarmState& swarm, int tick, Rng& rng);
  /// The tick event `index` fires at this run (known from tick 1 on).
  int tick_of(std::size_t index) const { return ticks_[index]; }
  /// The (side, block) change `change` of event `index` resolved to this run (0 = every).
  std::pair<int, int> target_of(std::size_t index, std::size_t change) const;

 private:
  void apply(const MissionEvent::LedChange& change, int side, int block, SwarmState& swarm) const;

  const std::vector<MissionEvent>* events_;
  const LedArena* led_arena_;
  std::vector<int> ticks_;
  std::vector<std::size_t> first_target_;    // per event, into targets_
  std::vector<std::pair<int, int>> targets_;  // per LED change, its side and block this run
};

}  // namespace sd
