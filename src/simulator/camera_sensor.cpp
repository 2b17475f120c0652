#include <algorithm>
#include <cmath>

#include "simulator/epuck.hpp"
#include "simulator/neighbour_grid.hpp"
#include "simulator/sensors.hpp"

namespace sd {

void sense_camera(const ArenaModel& arena, const RobotModel& model, SwarmState& swarm, Rng* rng) {
  // argos3-epuck's rot_z_only camera (epuck_omnidirectional_camera_sensor.cpp) keeps an LED
  // when |dx| and |dy| of its offset from the camera are both below the ground half-range
  // 0.122 tan 70 deg: a square aligned with the world axes, not a disc, and the height
  // difference does not count.
  const double half_range = model.camera_range;
  auto in_view = [half_range](Vec2 offset) { return std::abs(offset.x) < half_range && std::abs(offset.y) < half_range; };
  // argos3-epuck adds its noise to a blob in view: a vector of length N(0, s) in a uniformly
  // random direction, after the range and occlusion checks.
  const double noise = rng != nullptr ? model.camera_noise : 0.0;
  for (int i = 0; i < swarm.size; ++i) {
    const auto r = static_cast<std::size_t>(i);
    CameraBlob* out = swarm.blobs.data() + r * static_cast<std::size_t>(swarm.blobs_per_robot);
    std::uint16_t count = 0;
    if (!(swarm.demand[r] & SwarmState::kDemandCamera)) {
      swarm.blob_count[r] = 0;
      continue;
    }
    const Vec2 p = swarm.position[r], h = swarm.heading[r];
    const Vec3 camera{p.x, p.y, epuck::kCameraElevation};
    auto add = [&](std::uint32_t rgb, Vec2 offset) {
      if (noise > 0.0) {
        const double length = noise * rng->normal();
        offset += Vec2::polar(length, rng->uniform(0.0, 2.0 * kPi));
      }
      const double d = offset.length();
      const Vec2 local{h.x * offset.x + h.y * offset.y, h.x * offset.y - h.y * offset.x};
      out[count++] = {rgb, d > 0.0 ? local * (1.0 / d) : Vec2{1.0, 0.0}, d * 100.0};
    };
    // Robots never occlude LEDs: the ray stays above their 7.6 cm tops down to 7.65 cm.
    auto see_robot = [&](int j) {
      const std::uint32_t rgb = swarm.led[static_cast<std::size_t>(j)];
      if (rgb == 0 || j == i) return;
      const Vec2 led = swarm.position[j] + swarm.heading[j] * kRgbLedOffset;
      const Vec2 offset = led - p;
      if (!in_view(offset)) return;
      if (!arena.camera_line_of_sight(camera, {led.x, led.y, epuck::kRgbLedElevation})) return;
      add(rgb, offset);
    };
    if (!swarm.broad_phase.use_grid) {
      for (int j = 0; j < swarm.size; ++j) see_robot(j);
    } else {  // the robots whose LED can be in view, in index order as above
      const NeighbourGrid& grid = swarm.broad_phase.grid;
      std::uint16_t* candidate = swarm.broad_phase.candidates.data();
      std::size_t found = 0;
      grid.for_each_run_near(p, p, half_range - kRgbLedOffset, [&](int begin, int end) {
        for (int k = begin; k < end; ++k) candidate[found++] = grid.robot()[k];
      });
      std::sort(candidate, candidate + found);
      for (std::size_t k = 0; k < found; ++k) see_robot(candidate[k]);
    }
    for (std::size_t k = 0; k < arena.leds.size(); ++k) {
      const std::uint32_t rgb = swarm.arena_led_color[k];
      if (rgb == 0) continue;
      const ArenaLed& led = arena.leds[k];
      const Vec2 offset = led.position.xy() - p;
      if (!in_view(offset)) continue;
      if (!arena.camera_line_of_sight(camera, led.position, led.wall)) continue;
      add(rgb, offset);
    }
    swarm.blob_count[r] = count;
  }
}

}  // namespace sd
