#pragma once
// Per-robot deviations of a run: each robot's own fixed gains (RobotModel's *_deviation),
// drawn once per run. Empty (`active` false) in the design model.
#include <cstdint>
#include <vector>

#include "simulator/robot_model.hpp"

namespace sd {

struct RobotDeviations {
  bool active = false;
  std::vector<double> wheel_left, wheel_right;  // speed gains
  std::vector<double> proximity, light;          // reading gains
  std::vector<double> rab_range;                 // m, each robot's emission range

  /// Draws every robot's gains for the run with `seed` from a stream of their own (the run's
  /// Rng is untouched). Inactive, and allocation-free after the first run, when the model has
  /// no deviations.
  void draw(const RobotModel& model, int robots, std::uint64_t seed);
};

}  // namespace sd
