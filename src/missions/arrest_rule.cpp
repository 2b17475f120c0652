#include "missions/arrest_rule.hpp"

#include <cmath>

#include "missions/read_shapes.hpp"
#include "simulator/epuck.hpp"
#include "simulator/placement.hpp"

namespace sd {

namespace {

bool is_free(const ArenaModel& arena, const SwarmState& swarm, int robot, Vec2 p) {
  constexpr double r = epuck::kBodyRadius;
  for (const Wall& wall : arena.walls)
    if (wall.distance(p, nullptr) < r) return false;
  for (int j = 0; j < swarm.size; ++j)
    if (j != robot && (swarm.position[static_cast<std::size_t>(j)] - p).squared_length() < 4.0 * r * r) return false;
  return true;
}

bool is_allowed(const ArrestRule& rule, Vec2 p) {
  for (const Zone& z : rule.allowed)
    if (zone_contains(z, p)) return true;
  return false;
}

}  // namespace

ArrestRule read_arrest_rule(const Field& f) {
  f.only({"allowed", "jail", "trials"});
  ArrestRule rule;
  const Field allowed = f.at("allowed");
  if (allowed.items() == 0) allowed.fail("give at least one zone");
  for (std::size_t i = 0; i < allowed.items(); ++i) rule.allowed.push_back(read_zone(allowed.at(i)));
  rule.jail = read_region(f.at("jail"));
  const Vec2 jail_center = (rule.jail.bounds().first + rule.jail.bounds().second) * 0.5;
  if (!is_allowed(rule, jail_center))
    f.at("jail").fail("must lie in an allowed zone, or jailed robots would be arrested again every tick");
  if (f.has("trials")) rule.trials = f.at("trials").integer_in(1, 100000);
  return rule;
}

int apply_arrest_rule(const ArrestRule& rule, const ArenaModel& arena, SwarmState& swarm, Rng& rng) {
  int moved = 0;
  for (int i = 0; i < swarm.size; ++i) {
    const auto r = static_cast<std::size_t>(i);
    if (is_allowed(rule, swarm.position[r])) continue;
    for (int trial = 0; trial < rule.trials; ++trial) {
      const Vec2 p = sample_point(rule.jail, rng);
      const double yaw = wrap_signed(rng.uniform(0.0, kTwoPi));
      if (!is_free(arena, swarm, i, p)) continue;
      swarm.position[r] = p;
      swarm.yaw[r] = yaw;
      swarm.heading[r] = Vec2::polar(1.0, yaw);
      swarm.velocity[r] = {};
      ++moved;
      break;
    }
  }
  return moved;
}

}  // namespace sd
