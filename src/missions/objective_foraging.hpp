#pragma once
// Foraging with a per-robot carry state (the loop functions ForagingTwoSpotsLoopFunc of Vanilla
// and Coconut, TuttiFrLoopFunc of TuttiFrutti). Every tick, for each robot in index order (its
// identity, stable across ticks): if its centre is in a source, it now carries that source's
// item (a later source overwrites an earlier item); otherwise, if it is in the nest and carries
// an item, the item is delivered: F += the source's value, and it carries nothing.
// Vanilla: two sources of value 1 (F = deliveries); Coconut: value -1 (F = -deliveries,
// minimised); TuttiFrutti: +1 and -1 (F = deliveries from source 1 - from source 2).
#include <vector>

#include "missions/objective_base.hpp"
#include "missions/zone.hpp"

namespace sd {

class ForagingScore;

struct ForagingObjective {
  using Score = ForagingScore;
  struct Source {
    Zone zone;
    double value = 1.0;
  };
  std::vector<Source> sources;  // the first that contains the robot wins
  Zone nest;
};

/// {"sources": [{"region": ZONE, "value": 1}, ...], "nest": ZONE}
ForagingObjective read_foraging(const Field& f);

class ForagingScore {
 public:
  ForagingScore(const ForagingObjective& params, RunContext run);
  void reset();
  void post_step(const SwarmState& swarm, int tick, Rng& rng);
  double value() const { return value_; }
  /// Index of the source whose item robot i carries, or kNothing.
  int carried(int robot) const { return carrying_[static_cast<std::size_t>(robot)]; }
  static constexpr int kNothing = -1;

 private:
  const ForagingObjective* params_;
  std::vector<int> carrying_;
  double value_ = 0.0;
};

}  // namespace sd
