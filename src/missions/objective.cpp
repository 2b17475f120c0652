#include "missions/objective.hpp"

#include <variant>

namespace sd {

namespace {
template <class... Ts>
struct Overloaded : Ts... {
  using Ts::operator()...;
};
template <class... Ts>
Overloaded(Ts...) -> Overloaded<Ts...>;
}  // namespace

void ObjectiveTracker::post_step(const SwarmState& swarm, int /*tick*/, Rng& /*rng*/) {
  std::visit(Overloaded{[&](const objectives::RobotsInRegionPerTick& o) {
               int count = 0;
               for (int i = 0; i < swarm.size; ++i) count += o.region.contains(swarm.position[static_cast<std::size_t>(i)]);
               value_ += count;
             }},
             spec_->parameters);
}

}  // namespace sd
