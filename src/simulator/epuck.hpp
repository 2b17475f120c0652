#pragma once
// The e-puck as simulated by ARGoS3 (dynamics2d) + argos3-epuck: fixed
// geometry and constants. What a mission may change lives in RobotModel (robot_model.hpp).
#include <array>

#include "core/branchless.hpp"
#include "core/geometry.hpp"

namespace sd::epuck {

inline constexpr double kBodyRadius = 0.035;     // m
inline constexpr double kBodyHeight = 0.076;     // m, for ray occlusion
inline constexpr double kInterwheelDistance = 0.053;
inline constexpr double kMass = 0.4;             // kg
inline constexpr double kMaxDriveForce = 1.5;    // N, dynamics2d differential-steering joint
inline constexpr double kMaxWheelSpeedCm = 12.0; // cm/s, reference-model cap

inline constexpr double kTickSeconds = 0.1;
inline constexpr int kPhysicsSubsteps = 10;
inline constexpr double kSubstepSeconds = kTickSeconds / kPhysicsSubsteps;

// Proximity: rays from a ring just outside the body, at 11.25 deg + 45 deg k ...
inline constexpr int kProximitySensors = 8;
inline constexpr double kProximityRingRadius = 0.036;
inline constexpr double kProximityRange = 0.05;
inline constexpr double kProximityFirstRayDegrees = 11.25;
// ... but reported to the controller at the real e-puck's angles (pi / 10.5884, ...).
inline const std::array<double, 8> kSensorAngles = {
    kPi / 10.5884, kPi / 3.5999, kPi / 2.0, kPi / 1.2, kPi / 0.8571, kPi / 0.6667, kPi / 0.5806, kPi / 0.5247};

inline constexpr int kLightSensors = 8;  // same reported angles as proximity

// Ground: three points in front of the wheels; index 0 Left, 1 Centre, 2 Right.
inline constexpr int kGroundSensors = 3;
inline constexpr std::array<Vec2, 3> kGroundSensorOffsets = {Vec2{0.03, 0.009}, Vec2{0.03, 0.0}, Vec2{0.03, -0.009}};

inline constexpr double kRabElevation = 0.052;      // m; below the body top, so bodies occlude
inline constexpr double kRabRangeOffsetCm = 7.0;    // reported range = centre distance in cm - 2 radii
inline constexpr double kCameraElevation = 0.122;
inline constexpr double kRgbLedElevation = 0.0765;

/// Proximity reading of a hit at distance d (m) from the sensor point (argos3-epuck
/// CalculateReading): a quadratic fit, 0 beyond the range, clamped to [0, 1]. Branch-free:
/// whether a ray hit anything is a coin toss inside a cluster.
inline double proximity_reading(double d) {
  const double v = 298.701 * d * d - 36.8961 * d + 1.08212;
  return select(d > kProximityRange, 0.0, clamp01(v));
}

}  // namespace sd::epuck
