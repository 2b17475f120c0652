#include "missions/objective_foraging.hpp"

#include <algorithm>

#include "missions/read_shapes.hpp"

namespace sd {

ForagingObjective read_foraging(const Field& f) {
  f.only({"type", "direction", "sources", "nest"});
  ForagingObjective o;
  const Field sources = f.at("sources");
  if (sources.items() == 0) sources.fail("give at least one source");
  for (std::size_t i = 0; i < sources.items(); ++i) {
    const Field s = sources.at(i);
    s.only({"region", "value"});
    o.sources.push_back({read_zone(s.at("region")), s.number_or("value", 1.0)});
  }
  o.nest = read_zone(f.at("nest"));
  return o;
}

ForagingScore::ForagingScore(const ForagingObjective& params, RunContext run)
    : params_(&params), carrying_(static_cast<std::size_t>(run.robots), kNothing) {}

void ForagingScore::reset() {
  std::fill(carrying_.begin(), carrying_.end(), kNothing);
  value_ = 0.0;
}

void ForagingScore::post_step(const SwarmState& swarm, int /*tick*/, Rng& /*rng*/) {
  const auto& sources = params_->sources;
  for (std::size_t i = 0; i < carrying_.size(); ++i) {
    const Vec2 p = swarm.position[i];
    int source = kNothing;
    for (std::size_t k = 0; k < sources.size() && source == kNothing; ++k)
      if (zone_contains(sources[k].zone, p)) source = static_cast<int>(k);
    if (source != kNothing) {
      carrying_[i] = source;
    } else if (carrying_[i] != kNothing && zone_contains(params_->nest, p)) {
      value_ += sources[static_cast<std::size_t>(carrying_[i])].value;
      carrying_[i] = kNothing;
    }
  }
}

}  // namespace sd
