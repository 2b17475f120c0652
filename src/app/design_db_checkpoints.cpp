#include "app/design_db_checkpoints.hpp"

#include "design/state.hpp"

namespace sd::app {

namespace {

bool was_elite(const design::DesignState& s, int id) {
  if (s.first_race) return false;
  for (const auto& e : s.elites)
    if (e.id == id) return true;
  return false;
}

}  // namespace

void DesignDbCheckpoints::save(const design::Checkpoint& c, std::span<const design::Elimination> eliminations) {
  const design::DesignState& s = c.state;
  storage::CheckpointRows rows;
  for (std::size_t i = c.first_new_configuration; i < s.configurations.size(); ++i) {
    const auto& r = s.configurations.all()[i];
    rows.configurations.push_back({r.id, r.parent, s.iteration, design::record_to_json(r).at(2).dump(), space_.render(r.config)});
  }
  for (std::size_t i = c.first_new_experiment; i < s.experiments.size(); ++i) {
    const auto& e = s.experiments[i];
    rows.experiments.push_back({static_cast<std::int64_t>(i + 1), e.iteration, static_cast<std::int64_t>(e.position),
                                static_cast<std::int64_t>(s.instances.at(e.position).seed), e.configuration_id, e.cost});
  }
  if (s.race && s.iteration > store_.race_logged()) {
    storage::CheckpointRows::Race race{s.iteration, static_cast<std::int64_t>(s.current_budget), {}};
    for (const int id : s.race->config_ids) race.members.emplace_back(id, was_elite(s, id));
    rows.race = std::move(race);
  }
  for (const auto& e : eliminations)
    rows.eliminations.push_back({e.iteration, e.configuration_id, static_cast<std::int64_t>(e.after_instances)});
  for (std::size_t i = store_.elite_iterations(); i < s.all_elites.size(); ++i) rows.new_elites.push_back(s.all_elites[i]);
  const nlohmann::json state = design::state_to_json(s, false);
  rows.phase = state.at("phase").get<std::string>();
  rows.state = state.dump();
  store_.append(rows);
}

std::optional<design::DesignState> DesignDbCheckpoints::load() {
  std::optional<storage::StoredCheckpoint> stored = store_.load();
  if (!stored) return std::nullopt;
  try {
    design::History history;
    for (const auto& c : stored->configurations)
      history.configurations.push_back(
          design::config_record_from_json(nlohmann::json::array({c.id, c.parent, nlohmann::json::parse(c.record)})));
    for (const auto& e : stored->experiments)
      history.experiments.push_back({e.iteration, static_cast<std::size_t>(e.position), e.configuration_id, e.cost});
    return design::state_from_json(nlohmann::json::parse(stored->state), std::move(history));
  } catch (const std::exception& e) {
    throw storage::DesignFolderError(store_.folder().string() + "/design.db holds a design state that cannot be read (" +
                                     e.what() + ")");
  }
}

}  // namespace sd::app
