#pragma once
// Scripted swarms for objective tests: every robot parked at one point, then moved by hand;
// end-time objectives read on them.
#include <gtest/gtest.h>

#include <cstdint>
#include <initializer_list>

#include "missions/objective.hpp"
#include "simulator/swarm.hpp"

namespace sd::test {

inline SwarmState swarm_parked_at(int robots, Vec2 parked) {
  SwarmState s;
  s.resize(robots);
  for (auto& p : s.position) p = parked;
  return s;
}

/// Robots 0, 1, ... at the given points; the others stay where they are.
inline void place(SwarmState& s, std::initializer_list<Vec2> points) {
  std::size_t i = 0;
  for (const Vec2 p : points) s.position[i++] = p;
}

/// An end-time objective on fixed positions: nothing before the last tick, then its value.
inline double end_time_value(const Mission& m, SwarmState& s, std::uint64_t seed = 1) {
  ObjectiveTracker objective(m);
  objective.reset();
  Rng rng(seed);
  objective.post_step(s, m.ticks - 1, rng);
  EXPECT_EQ(objective.value(), 0.0) << "scored before the last tick";
  objective.post_step(s, m.ticks, rng);
  return objective.value();
}

}  // namespace sd::test
