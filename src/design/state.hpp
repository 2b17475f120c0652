#pragma once
// Everything a design process needs to continue after being killed: the iteration counters and
// budget, every configuration and experiment result, the model, the elites, the instance list,
// the generator state and the state of the race in progress. Serialised to JSON (nlohmann);
// restoring any checkpoint and continuing gives exactly the result of an uninterrupted run.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "design/rng_include.hpp"
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

/// `with_experiments = false` leaves out the experiment log (which the caller can store
/// incrementally: it is append-only) and the race's result table (rebuilt from the log).
nlohmann::json state_to_json(const DesignState& state, bool with_experiments = true);
/// `experiments`: the log when the JSON was written without it. Throws std::runtime_error on a
/// malformed document.
DesignState state_from_json(const nlohmann::json& j, std::optional<std::vector<ExperimentRecord>> experiments = {});

}  // namespace sd::design
