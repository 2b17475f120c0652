#pragma once
// Builds a SwarmState with robots at given poses, its pair table refreshed, for
// the sensor and physics tests.
#include <initializer_list>
#include <utility>

#include "simulator/sensors.hpp"

namespace sd::test {

inline SwarmState robots(std::initializer_list<std::pair<Vec2, double>> poses, int arena_leds = 0) {
  SwarmState s;
  s.resize(static_cast<int>(poses.size()), arena_leds);
  std::size_t i = 0;
  for (const auto& [p, yaw] : poses) {
    s.position[i] = p;
    s.yaw[i] = yaw;
    s.heading[i] = Vec2::polar(1.0, yaw);
    ++i;
  }
  s.broad_phase.build(s.position);
  return s;
}

inline SwarmState one_robot(Vec2 p, double yaw) { return robots({{p, yaw}}); }

}  // namespace sd::test
