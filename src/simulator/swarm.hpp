#pragma once
// Everything about the swarm that changes during a run (the "data" of the model/data
// split): poses, velocities, wheel commands, LEDs and the raw sensor readings of the
// current tick. Arrays are sized once per evaluation; a tick never allocates.
#include <array>
#include <span>
#include <cstdint>
#include <vector>

#include "core/geometry.hpp"
#include "simulator/broad_phase.hpp"
#include "simulator/robot_deviations.hpp"

namespace sd {

/// A range-and-bearing packet as the receiver sees it.
struct RabPacket {
  double range_cm;   // centre distance in cm minus 7 (ARGoS e-puck convention)
  Vec2 direction;    // unit vector towards the sender, in the receiver's frame
  std::uint16_t sender;
  /// Bearing in (-pi, pi], as ARGoS reports it.
  double bearing() const { return direction.angle(); }
};

/// A colour blob seen by the omnidirectional camera.
struct CameraBlob {
  std::uint32_t rgb;
  Vec2 direction;      // unit vector towards the LED, in the robot's frame
  double distance_cm;  // horizontal distance
  double angle() const { return direction.angle(); }
};

/// Scratch of the range-and-bearing sensor within its pass: nothing here outlives a tick.
struct SensorWorkspace {
  /// The pairs kept by the range and loss filters, and per kept pair who receives (bit 0:
  /// a, bit 1: b).
  std::vector<std::uint32_t> rab_pairs;
  std::vector<std::uint64_t> rab_receivers;

  void resize(std::size_t robots);
};

struct SwarmState {
  int size = 0;

  std::vector<Vec2> position;
  std::vector<double> yaw;
  std::vector<Vec2> heading;                   // (cos yaw, sin yaw), refreshed after physics
  std::vector<Vec2> velocity;                  // body velocity, world frame
  std::vector<double> angular_velocity;        // body angular velocity (rad/s)
  std::vector<double> wheel_left, wheel_right; // m/s, applied during the next physics step
  std::vector<std::uint32_t> led;              // RGB LEDs colour, 0 = off
  std::vector<std::uint32_t> arena_led_color;  // per ArenaModel::leds, 0 = off

  // Raw sensor readings of this tick, in [0, 1].
  std::vector<std::array<double, 8>> proximity;
  std::vector<std::array<double, 8>> light;
  std::vector<std::array<double, 3>> ground;   // left, centre, right
  // Range-and-bearing packets received this tick: rab[i * (size - 1) + k], k < rab_count[i].
  std::vector<RabPacket> rab;
  std::vector<std::uint16_t> rab_count;
  // Camera blobs this tick (only filled when a controller uses the camera).
  std::vector<CameraBlob> blobs;
  std::vector<std::uint16_t> blob_count;
  int blobs_per_robot = 0;

  /// Each robot's own fixed gains for this run (a pseudo-reality's per-robot deviations);
  /// inactive in the design model.
  RobotDeviations deviations;

  /// The robot pairs of this tick, built by sense after physics and read by the sensors
  /// and by the next physics step.
  BroadPhase broad_phase;

  /// Per robot, which memoryless sensors its control software reads at the coming control
  /// step (SensorDemand bits; all by default). Proximity, light and camera readings feed
  /// nothing that outlives the step, so a robot that does not read them is not sensed for
  /// them; ground and range-and-bearing feed the reference model's filter and buffer and
  /// are sensed for every robot whenever the software uses them at all.
  enum SensorDemand : std::uint8_t { kDemandProximity = 1, kDemandLight = 2, kDemandCamera = 4, kDemandAll = 7 };
  std::vector<std::uint8_t> demand;

  /// The sensors' scratch (not state of the swarm): kept here, sized with it, so that a
  /// tick allocates nothing.
  SensorWorkspace sensing;

  void resize(int robots, int arena_leds = 0);
  /// Chooses how pairs are found (resize picks the faster for the swarm's size); scores do
  /// not depend on it. For tests and benchmarks.
  void use_neighbour_grid(bool on);
  std::size_t rab_stride() const { return static_cast<std::size_t>(size > 1 ? size - 1 : 1); }
};

}  // namespace sd
