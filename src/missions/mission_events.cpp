#include "missions/mission_events.hpp"

#include "missions/read_shapes.hpp"

namespace sd {

namespace {

int read_selector(const Field& parent, const char* key, int count, const char* what) {
  if (!parent.has(key)) return MissionEvent::kEvery;
  const Field f = parent.at(key);
  if (f.is_text()) {
    const std::string s = f.text();
    if (s == "every") return MissionEvent::kEvery;
    if (s == "random") return MissionEvent::kRandom;
    f.fail("expected a " + std::string(what) + " number, \"every\" or \"random\"");
  }
  return f.integer_in(1, count);
}

}  // namespace

MissionEvent read_mission_event(const Field& f, const LedArena& led_arena, int mission_ticks) {
  f.only({"name", "tick", "set_leds"});
  MissionEvent event;
  event.name = f.at("name").text();
  if (event.name.empty()) f.at("name").fail("must not be empty");
  const Field tick = f.at("tick");
  if (tick.is_object()) {
    tick.only({"uniform"});
    const Field range = tick.at("uniform");
    if (range.items() != 2) range.fail("expected [first, last]");
    event.first_tick = range.at(0).integer_in(1, mission_ticks);
    event.last_tick = range.at(1).integer_in(event.first_tick, mission_ticks);
  } else {
    event.first_tick = event.last_tick = tick.integer_in(1, mission_ticks);
  }
  const Field leds = f.at("set_leds");
  if (leds.items() == 0) leds.fail("give at least one change");
  if (led_arena.empty()) leds.fail("the arena has no LED walls (arena.walls needs a led_polygon)");
  for (std::size_t i = 0; i < leds.items(); ++i) {
    const Field c = leds.at(i);
    c.only({"side", "block", "color"});
    MissionEvent::LedChange change;
    change.side = read_selector(c, "side", led_arena.sides, "side");
    change.block = read_selector(c, "block", led_arena.blocks_per_side, "block");
    change.color = read_color(c.at("color"));
    event.leds.push_back(change);
  }
  return event;
}

EventTimeline::EventTimeline(const std::vector<MissionEvent>& events, const LedArena& led_arena)
    : events_(&events), led_arena_(&led_arena), ticks_(events.size(), 0) {
  for (const MissionEvent& e : events) {
    first_target_.push_back(targets_.size());
    targets_.resize(targets_.size() + e.leds.size());
  }
}

void EventTimeline::reset() {
  std::fill(ticks_.begin(), ticks_.end(), 0);
  std::fill(targets_.begin(), targets_.end(), std::pair{0, 0});
}

std::pair<int, int> EventTimeline::target_of(std::size_t index, std::size_t change) const {
  return targets_[first_target_[index] + change];
}

void EventTimeline::post_step(SwarmState& swarm, int tick, Rng& rng) {
  const auto& events = *events_;
  if (tick == 1) {
    // ARGoS ranges are [min, max): U{a..b} is uniform_int(a, b + 1).
    for (std::size_t e = 0; e < events.size(); ++e) {
      const MissionEvent& event = events[e];
      ticks_[e] = event.first_tick == event.last_tick
                      ? event.first_tick
                      : static_cast<int>(rng.uniform_int(static_cast<std::uint32_t>(event.first_tick),
                                                         static_cast<std::uint32_t>(event.last_tick) + 1));
      for (std::size_t c = 0; c < event.leds.size(); ++c) {
        const MissionEvent::LedChange& change = event.leds[c];
        auto resolve = [&](int selector, int count) {
          return selector == MissionEvent::kRandom ? static_cast<int>(rng.uniform_int(1, static_cast<std::uint32_t>(count) + 1))
                                                   : selector;
        };
        const int side = resolve(change.side, led_arena_->sides);
        targets_[first_target_[e] + c] = {side, resolve(change.block, led_arena_->blocks_per_side)};
      }
    }
  }
  for (std::size_t e = 0; e < events.size(); ++e) {
    if (ticks_[e] != tick) continue;
    for (std::size_t c = 0; c < events[e].leds.size(); ++c) {
      const auto [side, block] = target_of(e, c);
      apply(events[e].leds[c], side, block, swarm);
    }
  }
}

void EventTimeline::apply(const MissionEvent::LedChange& change, int side, int block, SwarmState& swarm) const {
  for (const LedArena::Block& b : led_arena_->blocks) {
    if ((side != MissionEvent::kEvery && b.side != side) || (block != MissionEvent::kEvery && b.block != block)) continue;
    for (std::uint16_t k = 0; k < b.led_count; ++k) swarm.arena_led_color[b.first_led + k] = change.color;
  }
}

}  // namespace sd
