#pragma once
// Maple's actions (ids 40-45): the six Chocolate behaviours as the behaviour-tree code base
// defines them (ARGoS3-AutoMoDe branch BehaviorTree, dd7167c), not master's. Three laws differ
// from Chocolate:
// - W(v) keeps the inner wheel at or above -0.5 x the maximum speed (max(-0.5, cos theta));
// - Exploration turns only when the proximity reading in front is >= 0.5 (master: >= 0.1);
// - Repulsion applies rep once (-A(rep) - 5 P), where master's grows with rep^2.
#include "core/rng.hpp"
#include "modules/behaviours.hpp"
#include "modules/catalogue.hpp"
#include "robot/reference_model.hpp"

namespace sd::maple {

/// The proximity reading from which the BT branch's Exploration sees an obstacle in front.
inline constexpr double kObstacleThreshold = 0.5;
/// The BT branch's inner-wheel bound, as a fraction of the maximum speed.
inline constexpr double kInnerWheelFloor = -0.5;

/// W(v) of the BT branch: outer wheel at 12 cm/s, inner at 12 max(-0.5, cos(angle of v)).
/// The zero vector stops the robot.
Actuation bounded_wheels_towards(Vec2 v);

// The laws of ids 40-45 are laws::maple (laws.hpp), defined in maple_behaviours.cpp.

}  // namespace sd::maple
