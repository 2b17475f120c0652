#pragma once
// Coverage measured by Monte-Carlo sample points, computed once on the final positions
// (experiments-loop-functions' ChocolateCFALoopFunc and ChocolateSPCLoopFunc). Each term draws
// `count` points from the run's generator; for each point, d = distance to the closest robot
// the term's filter accepts (or `missing_distance` if it accepts none); the term is weight *
// mean(d) / normalizer. F = max(at_least, offset + sum of the terms).
//   CFA: one term, points polar-uniform in the disc of 1.2 m (rho ~ U(0, R), theta ~ U(0,
//        2 pi): denser near the centre), robots not on a forbidden disc, missing 2.5,
//        weight -100, offset 250, at least 0: F = max(0, (2.5 - E[d]) * 100). The mean is
//        the corrected one: ChocolateCFALoopFunc's accumulation bug is not reproduced.
//   SPC: area term (uniform in the white square, robots on it, missing 0.85, / 0.08) plus
//        perimeter term (uniform angle on the circle, robots within 0.04 of it, missing
//        0.6, / 0.06). Minimise.
#include <limits>
#include <vector>

#include "missions/objective_base.hpp"
#include "missions/zone.hpp"

namespace sd {

/// Where sample points come from; every draw uses the run's generator.
struct PointSampler {
  enum class Kind {
    PolarDisc,  // rho ~ U(0, radius), then theta ~ U(0, 2 pi), around the circle's centre
    OnCircle,   // theta ~ U(0, 2 pi) on the circle
    UniformIn,  // uniform in the region (the placement sampler)
  };
  Kind kind = Kind::UniformIn;
  Region region;  // a circle for PolarDisc and OnCircle
  Vec2 draw(Rng& rng) const;
};

struct MeanDistanceTerm {
  PointSampler points;
  int count = 1000;
  RobotFilter robots;
  double missing_distance = 0.0;
  double weight = 1.0;
  double normalizer = 1.0;
};

class MeanDistanceScore;

struct MeanDistanceObjective {
  using Score = MeanDistanceScore;
  std::vector<MeanDistanceTerm> terms;
  double offset = 0.0;
  double at_least = -std::numeric_limits<double>::infinity();
};

/// {"terms": [{"points": {"polar_disc" | "on_circle": {"center", "radius"}} | {"uniform_in": REGION},
///             "count": N, "robots": FILTER, "missing_distance": d, "weight": w, "normalizer": n}, ...],
///  "offset": 0, "at_least": -inf}
MeanDistanceObjective read_mean_distance(const Field& f);

class MeanDistanceScore {
 public:
  MeanDistanceScore(const MeanDistanceObjective& params, RunContext run);
  void reset() { value_ = 0.0; }
  void post_step(const SwarmState& swarm, int tick, Rng& rng);
  double value() const { return value_; }
  /// One term's mean distance on the given positions (what post_step adds up at tick T).
  double mean_distance(const MeanDistanceTerm& term, const SwarmState& swarm, Rng& rng);

 private:
  const MeanDistanceObjective* params_;
  RunContext run_;
  std::vector<Vec2> selected_;  // the robots a term looks at
  double value_ = 0.0;
};

}  // namespace sd
