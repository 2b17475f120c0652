#include "modules/behaviours.hpp"

#include <cmath>

#include "simulator/epuck.hpp"

namespace sd {

namespace {

constexpr double kMax = epuck::kMaxWheelSpeedCm;

/// Vectors shorter than 0.1 become "straight ahead" (AutoMoDe's small-vector fallback).
Vec2 with_fallback(Vec2 v) { return v.squared_length() < 0.01 ? Vec2{1.0, 0.0} : v; }

Actuation exploration(double rwm, BehaviourMemory& m, const ReferenceModel& rm, Rng& rng) {
  if (!m.turning) {
    // The step that sees an obstacle still drives forward; the turn starts next step.
    const Vec2 p = rm.proximity;
    if (p.squared_length() >= 0.01 && p.x >= 0.0) {
      m.turning = true;
      m.turn_steps = static_cast<std::int32_t>(rng.uniform_int(0, static_cast<std::uint32_t>(rwm)));
      m.turn_left = p.y < 0.0;  // obstacle on the right: turn left
    }
    return {kMax, kMax, 0};
  }
  m.turn_steps -= 1;
  if (m.turn_steps <= 0) m.turning = false;
  return m.turn_left ? Actuation{-kMax, kMax, 0} : Actuation{kMax, -kMax, 0};
}

}  // namespace

Actuation wheels_towards(Vec2 v) {
  const double length = v.length();
  if (length == 0.0) return {};
  const double c = v.x / length;
  if (v.y > 0.0) return {kMax * c, kMax, 0};
  return {kMax, kMax * c, 0};
}

void reset_behaviour(BehaviourMemory& memory) { memory = BehaviourMemory{}; }

Actuation run_behaviour(const ModuleInstance& b, BehaviourMemory& memory, const ReferenceModel& rm, Rng& rng) {
  const auto& prm = b.parameters;
  switch (b.id) {
    case 10:
      return exploration(prm[0], memory, rm, rng);
    case 11:
      return {};
    case 12:
      return wheels_towards(with_fallback(rm.light - rm.proximity * 5.0));
    case 13:
      return wheels_towards(with_fallback(-rm.light - rm.proximity * 5.0));
    case 14: {
      const double alpha = std::trunc(prm[0]);  // stored as UInt8 by AutoMoDe
      return wheels_towards(with_fallback(rm.attraction(alpha) - rm.proximity * 6.0));
    }
    case 15: {
      const double alpha = std::trunc(prm[0]);
      // alpha enters twice (inside A and outside): repulsion grows with rep^2.
      return wheels_towards(with_fallback(rm.attraction(alpha) * -alpha - rm.proximity * 5.0));
    }
    default:
      return {};
  }
}

}  // namespace sd
