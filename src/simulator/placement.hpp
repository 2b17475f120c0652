#pragma once
// Initial placement (CoreLoopFunctions::MoveRobots): robot after robot, a uniform position
// in the start region and a uniform yaw, redrawn while it would overlap a wall or a robot
// placed before it. Walls flagged placed_after_robots are not avoided: ARGoS loop functions
// that add walls in Init after MoveRobots (the SCA shelter) leave robots overlapping them.
#include <functional>

#include "core/rng.hpp"
#include "simulator/arena.hpp"
#include "simulator/region.hpp"
#include "simulator/swarm.hpp"

namespace sd {

inline constexpr int kPlacementTrials = 1000;

/// Uniform point in a region; discs use the ELF a/b formula (uniform over the disc).
Vec2 sample_point(const Region& region, Rng& rng);

/// Places every robot; throws std::runtime_error if one cannot be placed in 1000 trials.
void place_robots(const ArenaModel& arena, const Region& start, SwarmState& swarm, Rng& rng);
/// The same with the positions drawn by `sample`, for missions with their own start
/// distribution (TuttiFrutti's GetRandomPosition).
void place_robots(const ArenaModel& arena, const std::function<Vec2(Rng&)>& sample, SwarmState& swarm, Rng& rng);

}  // namespace sd
