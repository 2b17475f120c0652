#pragma once
// The outer loop of irace 3.5 (R/irace.R `irace_run`): budget split, iterations, one race per
// iteration, elites, model. Costs are minimised; a caller with a maximisation objective returns
// the negated score from its cost function.
//
//   IteratedRace design(space, options, runner);
//   design.on_checkpoint([&](const Checkpoint& c) { save(state_to_json(c.state)); });
//   DesignResult r = design.run();            // or: design.restore(state); design.run();
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <unordered_map>
#include <vector>

#include "design/experiment_runner.hpp"
#include "design/parameter_space.hpp"
#include "design/state.hpp"

namespace sd::design {

/// How an iteration after the first draws its new configurations. The first race is always
/// uniform, as in irace; only Model is irace.
enum class Sampler {
  Model,          // irace: around the elites, from the model it learns (the default)
  Uniform,        // random search: uniform again, raced against the elites (Birattari's F-Race(RSD), iterated)
  Neighbourhood,  // iterated local search: an elite with one to three moves (design/neighbourhood.hpp)
};

struct IraceOptions {
  long long max_experiments = 0;       // budget in evaluations (required)
  std::size_t n_instances = 1;         // instances the evaluator knows (SwarmDesign: 1 mission)
  std::uint64_t seed = 0;
  int nb_iterations = 0;               // 0: floor(2 + log2 N_param)
  long long nb_experiments_per_iteration = 0;  // 0: remaining / (N_iter - j + 1)
  int nb_configurations = 0;           // 0: computed per iteration
  int min_nb_survival = 0;             // 0: floor(2 + log2 N_param)
  int mu = 5;
  int first_test = 5;
  int each_test = 1;
  double confidence = 0.95;
  bool elitist = true;
  int elitist_new_instances = 1;
  int elitist_limit = 2;
  bool soft_restart = true;
  double soft_restart_threshold = std::numeric_limits<double>::quiet_NaN();  // NaN: 10^-digits
  bool sample_instances = true;
  /// Deviation from irace (which only drops duplicate elites): a new configuration equal to one
  /// already in the race is redrawn (up to 100 times), so no budget goes to twins.
  bool unique_new_configurations = true;
  std::vector<Configuration> initial_configurations;  // raced first in iteration 1
  Sampler sampler = Sampler::Model;
};

struct Progress {
  int iteration = 0;
  int nb_iterations = 0;
  long long experiments_used = 0;  // including the current race
  long long budget = 0;
  std::size_t alive = 0;           // alive configurations in the current race
  std::size_t race_configurations = 0;
  std::size_t task = 0;            // instances processed in the current race
  int best_id = 0;                 // best so far in the current race (0: none yet)
  double best_mean = 0.0;          // its mean cost on the instances of this race
};

/// Handed to the checkpoint hook after every step (iteration start, race task, race end).
/// state.configurations / state.experiments from the given indices on are new since the last
/// checkpoint; both are append-only.
struct Checkpoint {
  const DesignState& state;
  std::size_t first_new_configuration;
  std::size_t first_new_experiment;
};

struct EliteSummary {
  int id = 0;
  Configuration configuration;
  double mean_cost = 0.0;   // over every instance position it was evaluated on
  std::size_t evaluations = 0;
};

struct DesignResult {
  std::vector<EliteSummary> elites;  // final elites, best first
  std::string finish_reason;
  long long experiments_used = 0;
  int iterations = 0;
};

/// N_iter and the minimum survivors: floor(2 + log2 N_param).
int default_nb_iterations(std::size_t nb_variable);
/// irace computeNbConfigurations (with the elitist saving and the 1024 cap).
int nb_configurations_for(long long current_budget, int iteration, int mu, int each_test, std::size_t n_elites,
                          std::size_t n_old_instances, int new_instances, int cap = 1024);
/// irace computeMinimumBudget.
long long minimum_budget(const IraceOptions& o, int min_survival, int nb_iterations);
/// Identifies a space and options (stored in checkpoints, compared on resume); needs no engine.
std::string fingerprint(const ParameterSpace& space, const IraceOptions& options);

class IteratedRace {
 public:
  IteratedRace(const ParameterSpace& space, IraceOptions options, ExperimentRunner& runner);

  void on_checkpoint(std::function<void(const Checkpoint&)> hook) { checkpoint_ = std::move(hook); }
  void on_progress(std::function<void(const Progress&)> callback) { progress_ = std::move(callback); }

  /// Continue from a checkpoint (throws std::runtime_error for a checkpoint of another space or
  /// other options).
  void restore(DesignState state);

  /// Runs to the end.
  DesignResult run();
  /// One step: start an iteration, one race task, or finish a race. False once finished.
  bool advance();

  const DesignState& state() const { return state_; }
  DesignResult result() const;
  /// Identifies the space and options; stored in checkpoints.
  std::string fingerprint() const;

 private:
  void initialise();
  void start_iteration();
  void finish_race_and_iteration();
  void finish(std::string reason);
  void emit_checkpoint();
  void emit_progress();
  double lookup(std::size_t position, int id) const;
  void record(std::size_t position, int id, double cost);
  RaceSettings race_settings() const;
  std::vector<int> sample_new(std::size_t n, const std::vector<int>& elite_ids, bool uniform);

  const ParameterSpace& space_;
  IraceOptions options_;
  ExperimentRunner& runner_;
  DesignState state_;
  Rng rng_;
  bool initialised_ = false;
  std::size_t checkpointed_configurations_ = 0;
  std::size_t checkpointed_experiments_ = 0;
  std::unordered_map<int, std::map<std::size_t, double>> results_;  // id -> position -> cost
  std::function<void(const Checkpoint&)> checkpoint_;
  std::function<void(const Progress&)> progress_;
};

}  // namespace sd::design
