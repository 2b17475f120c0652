#pragma once
// F = sum over ticks t = 1..T of the number of robots whose centre is in a zone, or with
// `outside` of those that are not: AAC, SCA (Chocolate), Coconut aggregation, TuttiFrutti
// aggregation (robots with y < 0.465).
#include "missions/objective_base.hpp"
#include "missions/zone.hpp"

namespace sd {

class RegionCountScore;

struct RegionCountObjective {
  using Score = RegionCountScore;
  Zone zone;
  bool outside = false;  // count the robots not in the zone
};

/// {"region": ZONE, "count": "inside" | "outside"}
RegionCountObjective read_region_count(const Field& f);

class RegionCountScore {
 public:
  RegionCountScore(const RegionCountObjective& params, RunContext) : params_(&params) {}
  void reset() { value_ = 0.0; }
  void post_step(const SwarmState& swarm, int tick, Rng& rng);
  double value() const { return value_; }

 private:
  const RegionCountObjective* params_;
  double value_ = 0.0;
};

}  // namespace sd
