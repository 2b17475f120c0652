#include "missions/objective_region_count.hpp"

#include "missions/read_shapes.hpp"

namespace sd {

RegionCountObjective read_region_count(const Field& f) {
  f.only({"type", "direction", "region", "count"});
  RegionCountObjective o;
  o.zone = read_zone(f.at("region"));
  if (f.has("count")) {
    const std::string count = f.at("count").text();
    if (count == "outside") o.outside = true;
    else if (count != "inside") f.at("count").fail("must be \"inside\" or \"outside\"");
  }
  return o;
}

void RegionCountScore::post_step(const SwarmState& swarm, int /*tick*/, Rng& /*rng*/) {
  int count = 0;
  for (int i = 0; i < swarm.size; ++i)
    count += zone_contains(params_->zone, swarm.position[static_cast<std::size_t>(i)]) != params_->outside;
  value_ += count;
}

}  // namespace sd
