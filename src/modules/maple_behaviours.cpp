#include "modules/maple_behaviours.hpp"

#include <algorithm>
#include <cmath>

#include "simulator/epuck.hpp"

namespace sd::maple {

namespace {

constexpr double kMax = epuck::kMaxWheelSpeedCm;

/// Vectors shorter than 0.1 become "straight ahead" (AutoMoDe's small-vector fallback).
Vec2 with_fallback(Vec2 v) { return v.squared_length() < 0.01 ? Vec2{1.0, 0.0} : v; }

/// The BT branch's Exploration: Chocolate's two-state law, but its obstacle test (the base
/// class's ObstacleInFront) needs a reading of 0.5 in the front half-plane.
Actuation exploration(double rwm, BehaviourMemory& m, const ReferenceModel& rm, Rng& rng) {
  if (!m.turning) {
    // The step that sees an obstacle still drives forward; the turn starts next step.
    const Vec2 p = rm.proximity;
    if (p.squared_length() >= kObstacleThreshold * kObstacleThreshold && p.x >= 0.0) {
      m.turning = true;
      m.turn_steps = static_cast<std::int32_t>(rng.uniform_int(0, static_cast<std::uint32_t>(rwm)));
      m.turn_left = p.y < 0.0;  // obstacle on the right: turn left
    }
    return {kMax, kMax};
  }
  m.turn_steps -= 1;
  if (m.turn_steps <= 0) m.turning = false;
  return m.turn_left ? Actuation{-kMax, kMax} : Actuation{kMax, -kMax};
}

}  // namespace

Actuation bounded_wheels_towards(Vec2 v) {
  const double length = v.length();
  if (length == 0.0) return {0.0, 0.0};
  // ComputeWheelsVelocityFromVector of the BT branch: Max(-0.5, Cos(angle)) for the inner wheel
  // (master dropped the bound with RM1.2). The outer wheel is 1, so the speed factor is 12.
  const double c = std::max(kInnerWheelFloor, v.x / length);
  if (v.y > 0.0) return {kMax * c, kMax};
  return {kMax, kMax * c};
}

Actuation run_behaviour(const ModuleInstance& b, BehaviourMemory& memory, const ReferenceModel& rm, Rng& rng) {
  const auto& prm = b.parameters;
  switch (b.id) {
    case 40:
      return exploration(prm[0], memory, rm, rng);
    case 41:
      return {0.0, 0.0};
    case 42:
      return bounded_wheels_towards(with_fallback(rm.light - rm.proximity * 5.0));
    case 43:
      return bounded_wheels_towards(with_fallback(-rm.light - rm.proximity * 5.0));
    case 44: {
      const double alpha = std::trunc(prm[0]);  // stored as UInt8 by AutoMoDe
      return bounded_wheels_towards(with_fallback(rm.attraction(alpha) - rm.proximity * 6.0));
    }
    case 45: {
      // The BT branch's Repulsion applies rep once, inside A(rep): -A(rep) - 5 P (master and
      // Chocolate multiply by rep again).
      const double alpha = std::trunc(prm[0]);
      return bounded_wheels_towards(with_fallback(-rm.attraction(alpha) - rm.proximity * 5.0));
    }
    default:
      return {0.0, 0.0};
  }
}

}  // namespace sd::maple
