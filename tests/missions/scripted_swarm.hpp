#pragma once
// Scripted swarms for objective tests: every robot parked at one point, then moved by hand.
#include <initializer_list>

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

}  // namespace sd::test
