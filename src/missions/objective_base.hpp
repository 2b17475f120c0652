#pragma once
// What every objective building block shares. Each objective type is one file pair
// objective_<idea>.{hpp,cpp} holding
//   - its parameters (a plain struct, read from the mission file by read_<idea>),
//   - its score: a per-run state object with reset(), post_step(swarm, tick, rng) called
//     after every tick (ARGoS PostStep, after that tick's physics and control) and value().
// Scores size their buffers in the constructor, so post_step never allocates, and draw any
// random sample from the run's generator, so a score is a pure function of the seed.
#include "core/rng.hpp"
#include "simulator/swarm.hpp"

namespace sd {

class Field;
class EventTimeline;

/// What a score is built for: swarm size N, number of ticks T (objectives "computed at the
/// end", ARGoS PostExperiment, finalise in post_step at tick T) and the run's mission events.
struct RunContext {
  int robots = 0;
  int ticks = 0;
  const EventTimeline* events = nullptr;
};

}  // namespace sd
