#include "missions/objective_best_region.hpp"

#include <algorithm>

#include "missions/read_shapes.hpp"

namespace sd {

BestRegionObjective read_best_region(const Field& f) {
  f.only({"type", "direction", "regions"});
  const Field list = f.at("regions");
  if (list.items() == 0) list.fail("give at least one region");
  BestRegionObjective o;
  for (std::size_t i = 0; i < list.items(); ++i) o.regions.push_back(read_zone(list.at(i)));
  return o;
}

BestRegionScore::BestRegionScore(const BestRegionObjective& params, RunContext run)
    : params_(&params), run_(run), counts_(params.regions.size()) {}

void BestRegionScore::post_step(const SwarmState& swarm, int tick, Rng& /*rng*/) {
  if (tick != run_.ticks) return;  // PostExperiment: the final positions only
  std::fill(counts_.begin(), counts_.end(), 0);
  for (int i = 0; i < swarm.size; ++i) {
    const Vec2 p = swarm.position[static_cast<std::size_t>(i)];
    for (std::size_t k = 0; k < params_->regions.size(); ++k)
      if (zone_contains(params_->regions[k], p)) {
        ++counts_[k];
        break;
      }
  }
  value_ = static_cast<double>(*std::max_element(counts_.begin(), counts_.end())) / run_.robots;
}

}  // namespace sd
