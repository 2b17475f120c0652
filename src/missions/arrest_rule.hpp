#pragma once
// The arrest rule of the Coconut unbounded workspace (AmmarHsn/loop_functions): after every
// tick, before scoring, a robot whose centre is in none of the `allowed` zones is moved to a
// uniformly random point of the jail with a uniform yaw, redrawn while it would overlap a wall
// or another robot (up to `trials` times; if all fail it stays for this tick). Jailed robots
// sit in an allowed zone, so they stay there.
#include <vector>

#include "core/rng.hpp"
#include "missions/zone.hpp"
#include "simulator/arena.hpp"
#include "simulator/swarm.hpp"

namespace sd {

class Field;

struct ArrestRule {
  std::vector<Zone> allowed;
  Region jail;
  int trials = 100;
};

/// {"allowed": [ZONE, ...], "jail": REGION, "trials": 100}
ArrestRule read_arrest_rule(const Field& f);

/// Applies the rule to every robot, in index order; returns how many were moved.
int apply_arrest_rule(const ArrestRule& rule, const ArenaModel& arena, SwarmState& swarm, Rng& rng);

}  // namespace sd
