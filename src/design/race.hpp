#pragma once
// One F-race as irace 3.5 runs it (R/race.R `race`), cut into steps so that a design can be
// checkpointed after every batch of results: start_race() sets the instance order and loads the
// elites' old results, race_step() processes one task (one instance position), finish_race()
// ranks the survivors.
#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "design/experiment_runner.hpp"
#include "design/instance_list.hpp"
#include "design/records.hpp"

namespace sd::design {

struct RaceSettings {
  int first_test = 5;       // first elimination test after this many instances
  int each_test = 1;        // then every each_test instances
  double confidence = 0.95;
  bool elitist = true;
  int elitist_limit = 2;    // stop after this many tests without elimination (0 = never)
  int min_survival = 1;     // stop when this few survive
  long long max_experiments = 0;  // budget of this race (0 = unlimited)
};

/// Cost of configuration `id` at instance-list position `position`, NaN when never evaluated.
using ResultLookup = std::function<double(std::size_t position, int id)>;

struct RaceState {
  std::vector<int> config_ids;          // columns, race order: elites first
  std::vector<std::size_t> head;        // positions of the first tasks: new ones, then old ones permuted
  std::size_t future_begin = 1;         // then positions future_begin, future_begin + 1, ...
  std::size_t n_tasks = 0;
  std::size_t n_new = 0;                // elitist new instances raced first
  std::size_t n_old = 0;                // positions seen before this race
  bool has_elite_data = false;
  std::vector<std::vector<double>> results;  // rows = tasks (NaN = not run); rebuilt on restore
  std::vector<char> alive, rejected;
  std::vector<int> is_elite;            // old instances an elite has still to see before it can be dropped
  std::size_t elite_safe = 0;
  int no_elimination = 0;
  std::size_t next_task = 1;            // 1-based
  long long experiments_used = 0;
  std::size_t best = 0;                 // column of the best so far (for progress)
  bool finished = false;
  std::string stop_reason;
  /// Costs run ahead of their step, by (position, configuration id), until their step takes
  /// them. Not checkpointed: after a resume they are run again, to the same values.
  std::map<std::pair<std::size_t, int>, double> ahead;

  std::size_t position_of(std::size_t task) const {
    return task <= head.size() ? head[task - 1] : future_begin + (task - head.size() - 1);
  }
  std::size_t nb_alive() const;
};

struct RaceEnvironment {
  const ConfigurationStore& store;
  const InstanceList& instances;
  ExperimentRunner& runner;
  /// Called for every result, in batch order, before the step's elimination test.
  std::function<void(std::size_t position, int id, double cost)> record;
};

/// Sets up a race over `config_ids` (the first `n_elites` are the elites, whose earlier results
/// are read through `lookup` when elitist). `n_old`: positions seen before; `n_new`: new
/// instances to race first (0 in the first race); `n_positions`: size of the instance list.
RaceState start_race(const RaceSettings& settings, std::vector<int> config_ids, std::size_t n_elites,
                     std::size_t n_old, std::size_t n_new, std::size_t n_positions, bool sample_instances,
                     const ResultLookup& lookup, Rng& rng);

/// Processes the next task, or detects the end of the race (state.finished). Returns the number
/// of experiments evaluated (0 when the task needed none or the race ended).
std::size_t race_step(RaceState& state, const RaceSettings& settings, RaceEnvironment& env);

/// Refills state.results (after a restore) from the recorded results.
void rebuild_results(RaceState& state, std::size_t rows, const ResultLookup& lookup);

struct RaceResult {
  std::vector<int> ids;          // every configuration, sorted by rank (alive first)
  std::vector<double> ranks;     // Inf for eliminated ones
  std::vector<char> alive;
  std::size_t nb_alive = 0;
  std::vector<int> rejected_ids;
  long long experiments_used = 0;
};
/// Final ranking (irace overall.ranks): more instances first, then Friedman rank sums on the
/// instances all of a group share.
RaceResult finish_race(const RaceState& state);

/// irace overall.ranks on a matrix with NaN for missing results.
std::vector<double> overall_ranks(const std::vector<std::vector<double>>& results, const std::vector<std::size_t>& cols);

/// Elites for the next iteration (irace extractElites): alive, exact duplicates dropped (the
/// lower id kept), best min(alive, nb_elites) by rank with weights (N - r + 1) / (N (N + 1) / 2).
std::vector<Elite> extract_elites(const RaceResult& result, const ConfigurationStore& store, std::size_t nb_elites);

}  // namespace sd::design
