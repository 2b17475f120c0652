#pragma once
// LCN, the largest covering network (experiments-loop-functions' ChocolateLCNLoopFunc), on the
// final positions:
//  1. robots i, j are linked iff |p_i - p_j| < link_range (strict); connected components
//     are labelled in robot-index order;
//  2. G = the largest component (ties: the first labelled);
//  3. box = [min_x - s, max_x + s] x [min_y - s, max_y + s] over G, s = sensing_range. With
//     `box_max_from_zero` (the original's quirk) max_x and max_y start at 0 instead of
//     -infinity, so a group entirely at x < 0 still stretches the box to x = s;
//  4. n = ceil(w * h * samples_per_m2) points uniform in the box (x then y, from the run's
//     generator); a point counts if it is within s (<=) of a robot of G and in `clip`;
//  5. F = w * h * count / n, an estimate of the area covered by G. Maximise.
#include <cstdint>
#include <vector>

#include "missions/objective_base.hpp"
#include "missions/zone.hpp"

namespace sd {

class NetworkCoverageScore;

struct NetworkCoverageObjective {
  using Score = NetworkCoverageScore;
  double link_range = 0.35;
  double sensing_range = 0.25;
  Zone clip;                      // points outside do not count (LCN: |q| < 1.2)
  double samples_per_m2 = 100000;
  bool box_max_from_zero = true;
};

/// {"link_range", "sensing_range", "clip": ZONE, "samples_per_m2", "box_max_from_zero"}
NetworkCoverageObjective read_network_coverage(const Field& f);

class NetworkCoverageScore {
 public:
  NetworkCoverageScore(const NetworkCoverageObjective& params, RunContext run);
  void reset() { value_ = 0.0; }
  void post_step(const SwarmState& swarm, int tick, Rng& rng);
  double value() const { return value_; }
  /// Steps 1-2 on the given positions: the robots of the largest component, in index order.
  const std::vector<Vec2>& largest_component(const SwarmState& swarm);
  /// Steps 3-5 for the group found by largest_component.
  double covered_area(Rng& rng) const;

 private:
  const NetworkCoverageObjective* params_;
  RunContext run_;
  std::vector<std::int32_t> label_;
  std::vector<std::uint16_t> stack_;
  std::vector<Vec2> group_;
  double value_ = 0.0;
};

}  // namespace sd
