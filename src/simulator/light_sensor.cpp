#include <array>
#include <cmath>

#include "core/math.hpp"
#include "simulator/epuck.hpp"
#include "simulator/neighbour_grid.hpp"
#include "simulator/sensor_noise.hpp"
#include "simulator/sensors.hpp"

namespace sd {

namespace {

constexpr double kRadius = epuck::kBodyRadius;

}  // namespace

double ray_disc_entry(Vec2 origin, Vec2 direction, Vec2 center, double radius) {
  const Vec2 oc = origin - center;
  const double b = dot(oc, direction);
  const double c = oc.squared_length() - radius * radius;
  if (c <= 0.0) return 0.0;
  const double disc = b * b - c;
  if (disc < 0.0 || b > 0.0) return -1.0;
  return -b - std::sqrt(disc);
}

void sense_light(const ArenaModel& arena, const RobotModel& model, SwarmState& swarm, Rng& rng) {
  const int n = swarm.size;
  for (int i = 0; i < n; ++i) {
    std::array<double, 8>& reading = swarm.light[i];
    reading.fill(0.0);
    if (!(swarm.demand[i] & SwarmState::kDemandLight)) continue;
    const Vec2 p = swarm.position[i];
    for (std::size_t l = 0; l < arena.lights.size(); ++l) {
      const Light& light = arena.lights[l];
      if (light.intensity <= 0.0) continue;
      const Vec2 to_light = light.position.xy() - p;
      // Occlusion: the ray rises from the robot's ground point to the light; a body of
      // height H blocks it only within the first H / z of the way.
      bool occluded = false;
      for (const std::uint16_t w : arena.walls_shading(l, p)) {
        const double t = arena.light_clearance_fraction(l, arena.walls[w].height);
        // A robot inside a wall added after placement is not shaded by it: Chipmunk's segment
        // query ignores a shape the ray starts in (the same rule as the proximity rays').
        const Wall& wall = arena.walls[w];
        const double entry = wall.segment_entry(p, p + to_light * t);
        if (entry <= 1.0 && !(entry == 0.0 && wall.placed_after_robots && wall.contains(p))) {
          occluded = true;
          break;
        }
      }
      if (!occluded) {
        const double reach = to_light.length() * arena.light_clearance_fraction(l, epuck::kBodyHeight);
        const double reach_sq = (reach + kRadius) * (reach + kRadius);
        const Vec2 dir = to_light * (1.0 / to_light.length());
        auto blocks = [&](Vec2 center) {
          const double t = ray_disc_entry(p, dir, center, kRadius);
          return t >= 0.0 && t <= reach;
        };
        auto blocks_from = [&](int j) {
          return j != i && (swarm.position[j] - p).squared_length() < reach_sq && blocks(swarm.position[j]);
        };
        if (!swarm.broad_phase.use_grid) {
          for (int j = 0; j < n && !occluded; ++j) occluded = blocks_from(j);
        } else {  // a blocking body's centre lies within r of the ray's first `reach`
          const NeighbourGrid& grid = swarm.broad_phase.grid;
          grid.for_each_run_near(p, p + dir * reach, kRadius, [&](int begin, int end) {
            for (int k = begin; k < end && !occluded; ++k) occluded = blocks_from(grid.robot()[k]);
          });
        }
      }
      if (occluded) continue;
      const double dz = light.position.z;
      const double distance = std::sqrt(to_light.squared_length() + dz * dz) / light.intensity;
      if (distance > 2.5) continue;
      const double base = math::exp(-2.0 * distance);
      const double bearing = to_light.angle() - swarm.yaw[i];
      for (int k = 0; k < 8; ++k) {
        const double delta = std::abs(wrap_signed(bearing - epuck::kSensorAngles[k]));
        if (delta < kPi / 2.0) reading[k] += base * (1.0 - 2.0 * delta / kPi);
      }
    }
    if (swarm.deviations.active) scale_readings(reading, swarm.deviations.light[static_cast<std::size_t>(i)]);
    add_uniform_noise(reading, model.light_noise, rng);
  }
}

}  // namespace sd
