#pragma once
// Everything a design process needs to continue after being killed: the iteration counters and
// budget, every configuration and experiment result, the model, the elites, the instance list,
// the generator state and the state of the race in progress. Serialised to JSON (nlohmann);
// restoring any checkpoint and continuing gives exactly the result of an uninterrupted run.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "core/rng.hpp"
#include "design/instance_list.hpp"
#include "design/model.hpp"
#include "design/race.hpp"
#include "design/records.hpp"

namespace sd::design {

enum class Phase { StartIteration, Racing, Finished };

struct DesignState {
  std::string fingerprint;  // of the parameter space and options; a foreign checkpoint is refused
  Phase phase = Phase::StartIteration;
  int iteration = 1;        // j, 1-based
  int nb_iterations = 0;    // N_iter (grows when the budget outlasts it)
  int min_survival = 0;
  long long budget = 0;
  long long remaining_budget = 0;
  long long experiments_used = 0;
  long long current_budget = 0;
  int nb_configurations = 0;
  bool first_race = true;

  ConfigurationStore configurations;
  std::vector<int> rejected_ids;
  std::vector<Elite> elites;                  // current elites, best first
  std::vector<std::vector<int>> all_elites;   // per iteration, best first
  std::vector<char> soft_restarts;            // per iteration
  Model model;
  InstanceList instances;
  std::size_t positions_seen = 0;             // instance positions with at least one result
  std::vector<ExperimentRecord> experiments;  // append-only log
  std::optional<RaceState> race;
  Rng::State rng{};
  std::string finish_reason;
};

/// The append-only part of a state: every configuration and every result. A caller that
/// checkpoints often stores it incrementally (Checkpoint tells what is new) and writes the rest
/// with state_to_json(state, false), which stays small (tens of kB) whatever the budget.
struct History {
  std::vector<ConfigRecord> configurations;
  std::vector<ExperimentRecord> experiments;
};

/// `with_history = false` leaves out configurations and experiments (their counts are kept to
/// check the history handed back on restore). The race's result table is never written: it is
/// rebuilt from the experiments.
nlohmann::json state_to_json(const DesignState& state, bool with_history = true);
/// `history`: required when the JSON was written without it. Throws std::runtime_error on a
/// malformed document or a history that does not match.
DesignState state_from_json(const nlohmann::json& j, std::optional<History> history = {});

nlohmann::json record_to_json(const ConfigRecord& r);  // [id, parent, [values, null = NA]]
ConfigRecord config_record_from_json(const nlohmann::json& j);
nlohmann::json record_to_json(const ExperimentRecord& r);  // [iteration, position, id, cost]
ExperimentRecord experiment_record_from_json(const nlohmann::json& j);

}  // namespace sd::design
