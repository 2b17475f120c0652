#pragma once
// Raw sensing of one tick (argos3-epuck's simulated sensors): proximity rays, light, ground,
// range-and-bearing with line of sight and packet loss, and (when asked) the camera.
// Reads poses, writes the sensor arrays of SwarmState; draws noise from the run's Rng.
#include "core/rng.hpp"
#include "simulator/arena.hpp"
#include "simulator/broad_phase.hpp"
#include "simulator/epuck.hpp"
#include "simulator/robot_model.hpp"
#include "simulator/swarm.hpp"

namespace sd {

/// The sensors a run simulates: only those the control software reads (ARGoS likewise
/// skips disabled devices). Which ones a module reads is in the module catalogue.
struct SensorSet {
  bool proximity = true, light = true, ground = true, range_and_bearing = true, camera = false;
};

void sense_proximity(const ArenaModel& arena, const RobotModel& model, SwarmState& swarm, Rng& rng);
void sense_light(const ArenaModel& arena, const RobotModel& model, SwarmState& swarm, Rng& rng);
void sense_ground(const ArenaModel& arena, const RobotModel& model, SwarmState& swarm, Rng& rng);
void sense_range_and_bearing(const ArenaModel& arena, const RobotModel& model, SwarmState& swarm, Rng& rng);
/// Omnidirectional camera (RM3.0): a blob per lit LED of another robot (its rear RGB LED,
/// the one AutoMoDe lights in simulation) and per lit arena LED within range. With a
/// pseudo-reality's camera noise, its draws come from `rng` (none without it).
void sense_camera(const ArenaModel& arena, const RobotModel& model, SwarmState& swarm, Rng* rng = nullptr);

/// Where a robot's lit RGB LED is: index 2, at the rear, 1 mm outside the body.
inline constexpr double kRgbLedOffset = -0.036;

/// All of the above, in a fixed order (the order of random draws is part of determinism),
/// after building the tick's broad phase (swarm.broad_phase) from the poses. Each sensor
/// alone reads the broad phase as the last build left it.
void sense(const ArenaModel& arena, const RobotModel& model, SwarmState& swarm, Rng& rng, SensorSet sensors = {});

/// Entry distance along a ray (origin, unit direction) into a disc, or a negative value if
/// the ray misses it. An origin inside the disc gives 0.
double ray_disc_entry(Vec2 origin, Vec2 direction, Vec2 center, double radius);

}  // namespace sd
