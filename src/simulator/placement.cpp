#include "simulator/placement.hpp"

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

#include "simulator/epuck.hpp"

namespace sd {

Vec2 sample_point(const Region& region, Rng& rng) {
  switch (region.shape) {
    case Region::Shape::Circle: {
      double a = rng.uniform(), b = rng.uniform();
      if (b < a) std::swap(a, b);
      if (b <= 0.0) return region.center;
      return region.center + Vec2::polar(b * region.radius, kTwoPi * a / b);
    }
    case Region::Shape::Rectangle: {
      const Vec2 local{rng.uniform(-region.half_size.x, region.half_size.x), rng.uniform(-region.half_size.y, region.half_size.y)};
      const auto [s, c] = math::sincos(region.yaw);
      return region.center + Vec2{c * local.x - s * local.y, s * local.x + c * local.y};
    }
    case Region::Shape::Polygon: {
      const auto [lo, hi] = region.bounds();
      for (int trial = 0; trial < 100000; ++trial) {
        const Vec2 p{rng.uniform(lo.x, hi.x), rng.uniform(lo.y, hi.y)};
        if (region.contains(p)) return p;
      }
      throw std::runtime_error("start region polygon has no area");
    }
  }
  return region.center;
}

void place_robots(const ArenaModel& arena, const Region& start, SwarmState& swarm, Rng& rng) {
  place_robots(arena, [&start](Rng& g) { return sample_point(start, g); }, swarm, rng);
}

void place_robots(const ArenaModel& arena, const std::function<Vec2(Rng&)>& sample, SwarmState& swarm, Rng& rng) {
  constexpr double r = epuck::kBodyRadius;
  for (int i = 0; i < swarm.size; ++i) {
    bool placed = false;
    for (int trial = 0; trial < kPlacementTrials && !placed; ++trial) {
      const Vec2 p = sample(rng);
      const double yaw = rng.uniform(0.0, kTwoPi);
      bool free = true;
      for (const Wall& wall : arena.walls)
        if (!wall.placed_after_robots && wall.distance(p, nullptr) < r) { free = false; break; }
      for (int j = 0; j < i && free; ++j)
        if ((swarm.position[j] - p).squared_length() < 4.0 * r * r) free = false;
      if (free) {
        swarm.position[i] = p;
        swarm.yaw[i] = wrap_signed(yaw);
        swarm.heading[i] = Vec2::polar(1.0, swarm.yaw[i]);
        placed = true;
      }
    }
    if (!placed)
      throw std::runtime_error("cannot place robot " + std::to_string(i) + " in the start region after " +
                               std::to_string(kPlacementTrials) + " trials (too many robots for the region?)");
  }
  for (int i = 0; i < swarm.size; ++i) {
    swarm.velocity[i] = {};
    swarm.angular_velocity[i] = 0.0;
    swarm.wheel_left[i] = swarm.wheel_right[i] = 0.0;
    swarm.led[i] = 0;
  }
}

}  // namespace sd
