#pragma once
// Control laws of the behaviour modules (modules-and-grammar.md §3-4). A behaviour reads the
// reference model, may keep a little memory between steps, and sets the wheels (cm/s) and
// the RGB LEDs.
#include <cstdint>

#include "core/rng.hpp"
#include "modules/catalogue.hpp"
#include "robot/reference_model.hpp"

namespace sd {

/// What a behaviour remembers between control steps (Exploration's turn, for instance).
struct BehaviourMemory {
  bool turning = false;
  bool turn_left = false;
  std::int32_t turn_steps = 0;
};

struct Actuation {
  double left_cm = 0.0, right_cm = 0.0;  // wheel speeds, cm/s
  std::uint32_t led = 0;                 // RGB, 0 = off
};

/// W(v) of RM1.2: outer wheel at 12 cm/s, inner at 12 cos(angle of v). The zero vector
/// stops the robot (AutoMoDe would compute NaN speeds).
Actuation wheels_towards(Vec2 v);

void reset_behaviour(BehaviourMemory& memory);
Actuation run_behaviour(const ModuleInstance& behaviour, BehaviourMemory& memory, const ReferenceModel& rm, Rng& rng);

}  // namespace sd
