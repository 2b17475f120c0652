#include "design/race_log.hpp"

#include <utility>

namespace sd::design {

void EliminationTracker::reset(const DesignState& state) {
  iteration_ = state.race ? state.iteration : 0;
  alive_ = state.race ? state.race->alive : std::vector<char>{};
}

void EliminationTracker::observe(const DesignState& state) {
  if (!state.race) return;
  const RaceState& race = *state.race;
  if (state.iteration != iteration_ || alive_.size() != race.alive.size()) {
    iteration_ = state.iteration;  // a new race: everybody starts alive
    alive_.assign(race.alive.size(), 1);
  }
  for (std::size_t k = 0; k < race.alive.size(); ++k) {
    if (alive_[k] && !race.alive[k])
      pending_.push_back({state.iteration, race.config_ids[k], race.next_task - 1});
    alive_[k] = race.alive[k];
  }
}

std::vector<Elimination> EliminationTracker::take() { return std::exchange(pending_, {}); }

}  // namespace sd::design
