#include "design/checkpoint_store.hpp"

namespace sd::design {

void MemoryCheckpointStore::save(const Checkpoint& c, std::span<const Elimination> eliminations) {
  const DesignState& s = c.state;
  // Only what is new, as a database would append it: a store that re-copied everything would
  // hide a checkpoint that announces too little.
  for (std::size_t i = c.first_new_configuration; i < s.configurations.size(); ++i)
    history_.configurations.push_back(s.configurations.all()[i]);
  for (std::size_t i = c.first_new_experiment; i < s.experiments.size(); ++i)
    history_.experiments.push_back(s.experiments[i]);
  eliminations_.insert(eliminations_.end(), eliminations.begin(), eliminations.end());
  state_ = state_to_json(s, false);
  ++step_;
}

std::optional<DesignState> MemoryCheckpointStore::load() {
  if (!state_) return std::nullopt;
  return state_from_json(*state_, history_);
}

}  // namespace sd::design
