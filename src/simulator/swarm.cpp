#include "simulator/swarm.hpp"

namespace sd {

void SensorWorkspace::resize(std::size_t n) {
  const std::size_t slots = pair_count(n) + 1;  // one spare slot for the branch-free appends
  rab_pairs.assign(slots, 0);
  rab_receivers.assign(slots, 0);
}

void SwarmState::resize(int robots, int arena_leds) {
  size = robots;
  const auto n = static_cast<std::size_t>(robots);
  position.assign(n, {});
  yaw.assign(n, 0.0);
  heading.assign(n, {1.0, 0.0});
  velocity.assign(n, {});
  angular_velocity.assign(n, 0.0);
  wheel_left.assign(n, 0.0);
  wheel_right.assign(n, 0.0);
  led.assign(n, 0);
  demand.assign(n, kDemandAll);
  proximity.assign(n, {});
  light.assign(n, {});
  ground.assign(n, {});
  rab.assign(n * rab_stride(), {});
  rab_count.assign(n, 0);
  blob_count.assign(n, 0);
  arena_led_color.assign(static_cast<std::size_t>(arena_leds), 0);
  blobs_per_robot = static_cast<int>(rab_stride()) + arena_leds;
  blobs.assign(n * static_cast<std::size_t>(blobs_per_robot), {});
  sensing.resize(n);
  broad_phase.resize(n);
  use_neighbour_grid(robots >= kNeighbourGridFromRobots);
}

void SwarmState::use_neighbour_grid(bool on) { broad_phase.use_neighbour_grid(on, static_cast<std::size_t>(size)); }

}  // namespace sd
