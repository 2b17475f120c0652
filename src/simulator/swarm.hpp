#pragma once
// Everything about the swarm that changes during a run (the "data" of the model/data
// split): poses, velocities, wheel commands, LEDs and the raw sensor readings of the
// current tick. Arrays are sized once per evaluation; a tick never allocates.
#include <array>
#include <span>
#include <cstdint>
#include <vector>

#include "core/geometry.hpp"
#include "simulator/neighbour_grid.hpp"

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

/// One unordered pair of robots, refreshed every tick after physics.
struct RobotPair {
  std::uint16_t a, b;
  Vec2 delta;          // position[b] - position[a]
  double distance_sq;
};

/// Unordered pairs of `robots` robots: the length of SwarmState::pairs in a small swarm.
constexpr std::size_t pair_count(std::size_t robots) { return robots * (robots - 1) / 2; }

/// What the sensors derive from the poses each tick (update_pairs) or use within one
/// sensor's pass. Nothing here outlives a tick.
struct SensorWorkspace {
  /// Whether the pairs come from the neighbour grid (only those within pair_range, listed
  /// anew each tick) or are all pairs of the swarm. The same pairs within range, in the same
  /// order, either way: the grid only saves looking at far ones, which in a small swarm
  /// costs more than it saves.
  bool use_grid = false;
  NeighbourGrid grid;
  /// The centre distance within which SwarmState::pairs holds every pair (grid only).
  double pair_range = 0.0;
  /// Robots the grid offered one robot, sorted before use (grid only).
  std::vector<std::uint16_t> candidates;
  /// Indices into SwarmState::pairs of the pairs close enough for a proximity ray to meet
  /// the other body (the first close_pair_count entries).
  std::vector<std::uint32_t> close_pairs;
  int close_pair_count = 0;
  /// The positions as two plain arrays: the line-of-sight tests scan every robot at once,
  /// and contiguous coordinates let that scan vectorise.
  std::vector<double> position_x, position_y;

  /// True if the close pairs and the pair table were computed from exactly these positions
  /// (nothing moved a robot since update_pairs): then physics may take its contact
  /// candidates from them instead of scanning every pair again.
  bool describes(const std::vector<Vec2>& position) const {
    bool same = position.size() == position_x.size();
    for (std::size_t i = 0; same && i < position.size(); ++i) same = position[i].x == position_x[i] && position[i].y == position_y[i];
    return same;
  }
  /// Range and bearing: the pairs kept by the range and loss filters, and per kept pair who
  /// receives (bit 0: a, bit 1: b).
  std::vector<std::uint32_t> rab_pairs;
  std::vector<std::uint64_t> rab_receivers;

  void resize(std::size_t robots);
};

/// From this many robots on, pairs are found with the neighbour grid. In AAC's density
/// (bench/, BM_Scaling*) the grid is 1.2-1.4x faster than all pairs at 75-100 robots for
/// exploration and as fast for attraction; at 20-50 robots all pairs are faster.
inline constexpr int kNeighbourGridFromRobots = 75;

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

  /// Pairs i < j in lexicographic order: all of them in a small swarm, those within
  /// sensing.pair_range in a large one (see SensorWorkspace::use_grid).
  std::vector<RobotPair> pairs;

  /// Per robot, which memoryless sensors its control software reads at the coming control
  /// step (SensorDemand bits; all by default). Proximity, light and camera readings feed
  /// nothing that outlives the step, so a robot that does not read them is not sensed for
  /// them; ground and range-and-bearing feed the reference model's filter and buffer and
  /// are sensed for every robot whenever the software uses them at all.
  enum SensorDemand : std::uint8_t { kDemandProximity = 1, kDemandLight = 2, kDemandCamera = 4, kDemandAll = 7 };
  std::vector<std::uint8_t> demand;

  /// The sensors' working space (not state of the swarm): kept here, sized with it, so
  /// that a tick allocates nothing.
  SensorWorkspace sensing;

  void resize(int robots, int arena_leds = 0);
  /// Chooses how pairs are found (resize picks the faster for the swarm's size); scores do
  /// not depend on it. For tests and benchmarks.
  void use_neighbour_grid(bool on);
  std::size_t rab_stride() const { return static_cast<std::size_t>(size > 1 ? size - 1 : 1); }
};

}  // namespace sd
