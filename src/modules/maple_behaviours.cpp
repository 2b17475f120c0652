#include "modules/maple_behaviours.hpp"

#include <algorithm>
#include <cmath>

#include "simulator/epuck.hpp"

namespace sd::maple {

namespace {

constexpr double kMax = epuck::kMaxWheelSpeedCm;

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
      // The BT branch's obstacle test (the base class's ObstacleInFront) needs a reading of 0.5.
      return sd::exploration(prm[0], kObstacleThreshold * kObstacleThreshold, memory, rm, rng);
    case 41:
      return {0.0, 0.0};
    case 42:
      return bounded_wheels_towards(phototaxis_vector(rm));
    case 43:
      return bounded_wheels_towards(anti_phototaxis_vector(rm));
    case 44:
      return bounded_wheels_towards(attraction_vector(rm, prm[0]));
    case 45:
      // The BT branch's Repulsion applies rep once, inside A(rep): -A(rep) - 5 P.
      return bounded_wheels_towards(repulsion_vector(rm, prm[0], /*rep_squared=*/false));
    default:
      return {0.0, 0.0};
  }
}

}  // namespace sd::maple
