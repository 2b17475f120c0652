#pragma once
// End-time aggregation in the best of several regions (experiments-loop-functions'
// AggregationTwoSpotsLoopFunc for Vanilla aggregation, AggregationTwoSpotsXOR for
// aggregation-XOR): on the positions after the last tick, each robot counts for the first
// region that contains its centre; F = (largest count) / N, with N the mission's number of
// robots. In [0, 1].
#include <vector>

#include "missions/objective_base.hpp"
#include "missions/zone.hpp"

namespace sd {

class BestRegionScore;

struct BestRegionObjective {
  using Score = BestRegionScore;
  std::vector<Zone> regions;
};

/// {"regions": [ZONE, ZONE, ...]}
BestRegionObjective read_best_region(const Field& f);

class BestRegionScore {
 public:
  BestRegionScore(const BestRegionObjective& params, RunContext run);
  void reset() { value_ = 0.0; }
  void post_step(const SwarmState& swarm, int tick, Rng& rng);
  double value() const { return value_; }

 private:
  const BestRegionObjective* params_;
  RunContext run_;
  std::vector<int> counts_;
  double value_ = 0.0;
};

}  // namespace sd
