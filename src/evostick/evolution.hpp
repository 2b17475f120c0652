#pragma once
// EvoStick: the neuro-evolution baseline of the AutoMoDe papers, evolving the 50 weights of
// the Arlequin perceptron (arlequin.hpp) with a generational algorithm:
//
//   generation 1: the silent network (every weight 0) and population - 1 mutants of it
//     (the mutation below applied once);
//   every generation: draw `evaluations` seeds; run every network once per seed (the same
//     seeds for all, so networks are compared on the same conditions); rank the networks by
//     their mean score (ties keep the earlier network first);
//   next generation: the `elites` best unchanged (they are evaluated again on the next
//     generation's seeds, so a lucky draw does not stay on top), then population - elites
//     children, each a copy of a uniformly chosen elite in which every weight, with
//     probability `mutation_probability`, gets Gaussian noise N(0, sigma^2) and is clipped
//     to [-bound, bound].
//
// All randomness (initial weights, seeds, parents, noise) comes from one generator seeded by
// `seed`, drawn on the calling thread in a fixed order; runs go through an Evaluator, which
// returns scores by task index. The result is therefore a function of (mission or measure,
// settings) alone, whatever the number of threads.
#include <cstdint>
#include <functional>
#include <vector>

#include "core/rng.hpp"
#include "evaluation/evaluator.hpp"
#include "modules/arlequin.hpp"

namespace sd::evostick {

/// Defaults: the settings the AutoMoDe papers report for EvoStick (population 100, 10 runs
/// per individual, 20 elites, weights in [-5, 5]). The start and the mutation are ours,
/// chosen on short evolutions (src/evostick/README.md): the neighbour inputs 20-23 are in
/// cm (up to ~70), so a network with random weights in [-5, 5] is saturated by its
/// neighbours whatever else it senses, a flat landscape for selection; starting from the
/// silent network and mutating a few weights at a time (each with probability 0.3, noise of
/// sigma 1, a tenth of the weight range) keeps networks where their other inputs count.
struct Settings {
  int population = 100;
  int evaluations = 10;
  int elites = 20;
  double mutation_sigma = 1.0;
  double mutation_probability = 0.3;
  double weight_bound = arlequin::kWeightBound;
  int generations = 1;
  std::uint64_t seed = 1;

  /// Simulation runs of the whole evolution: generations x population x evaluations.
  std::int64_t runs() const;
  std::int64_t runs_per_generation() const;
  /// Throws std::invalid_argument naming the setting that is out of range.
  void validate() const;
};

/// The most generations whose runs fit in `budget` simulation runs; throws
/// std::invalid_argument if not even one fits.
int generations_for_budget(std::int64_t budget, const Settings& settings);

struct GenerationRecord {
  int generation = 0;            // 1-based
  double best_mean = 0.0;        // mean score of the generation's best network over its runs
  double population_mean = 0.0;  // mean of every network's mean score
  std::uint64_t best_digest = 0; // weight_digest of that best network
  bool operator==(const GenerationRecord&) const = default;
};

struct Result {
  arlequin::Weights best{};      // best network of the last generation
  double best_mean = 0.0;        // its mean score over that generation's runs
  std::vector<GenerationRecord> history;
  std::int64_t runs = 0;
  bool stopped = false;          // stopped between generations (`best` unset): resume from the state
};

using Progress = std::function<void(const GenerationRecord&)>;

/// What an evolution carries from one generation to the next: continuing from it gives
/// exactly what the uninterrupted evolution would have.
struct Checkpoint {
  int generation = 0;                         // generations done (0..generations - 1)
  std::vector<arlequin::Weights> population;  // the networks of generation `generation` + 1
  Rng::State rng{};
  Result result;                              // history and runs so far
};
using CheckpointSink = std::function<void(const Checkpoint&)>;

/// Evolves a network for `mission`, ranking by the scores `evaluator` returns in the given
/// direction. `progress` is called after every generation; `save`, if set, at the start and
/// after every generation but the last, with the state to continue from. `resume` continues
/// an evolution from such a state (made with the same settings). `stop`, if set, is asked after
/// every generation's state is saved: true ends the evolution there (Result::stopped).
using StopRequest = std::function<bool()>;
Result evolve(const Mission& mission, Direction direction, Evaluator& evaluator, const Settings& settings,
              const Progress& progress = {}, const Checkpoint* resume = nullptr, const CheckpointSink& save = {},
              const StopRequest& stop = {});

/// FNV-1a over the bit patterns of the weights: two networks have the same digest only if
/// (barring a collision) every weight is the same double.
std::uint64_t weight_digest(const arlequin::Weights& weights);

}  // namespace sd::evostick
