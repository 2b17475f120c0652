#include "evostick/evolution.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "core/fnv.hpp"
#include "core/rng.hpp"

namespace sd::evostick {

namespace {

ControlSoftware network_software() {
  ControlSoftware software;
  software.architecture = Architecture::NeuralNetwork;
  return software;
}

void mutate(arlequin::Weights& weights, const Settings& s, Rng& rng) {
  for (double& w : weights)
    if (rng.uniform() < s.mutation_probability)
      w = std::clamp(w + s.mutation_sigma * rng.normal(), -s.weight_bound, s.weight_bound);
}

/// The silent network (every weight 0: both wheels stopped, every input in the sigmoid's
/// sensitive range) and mutants of it.
std::vector<ControlSoftware> initial_population(const Settings& s, Rng& rng) {
  std::vector<ControlSoftware> population(static_cast<std::size_t>(s.population), network_software());
  for (std::size_t p = 1; p < population.size(); ++p) mutate(population[p].network.weights, s, rng);
  return population;
}

/// Elites first, in rank order, then mutated copies of uniformly chosen elites.
std::vector<ControlSoftware> next_generation(const std::vector<ControlSoftware>& population,
                                             const std::vector<std::size_t>& ranking, const Settings& s, Rng& rng) {
  std::vector<ControlSoftware> next;
  next.reserve(population.size());
  const auto elites = static_cast<std::size_t>(s.elites);
  for (std::size_t k = 0; k < elites; ++k) next.push_back(population[ranking[k]]);
  while (next.size() < population.size()) {
    ControlSoftware child = next[rng.below(static_cast<std::uint32_t>(elites))];
    mutate(child.network.weights, s, rng);
    next.push_back(std::move(child));
  }
  return next;
}

}  // namespace

std::int64_t Settings::runs_per_generation() const {
  return static_cast<std::int64_t>(population) * static_cast<std::int64_t>(evaluations);
}

std::int64_t Settings::runs() const { return static_cast<std::int64_t>(generations) * runs_per_generation(); }

void Settings::validate() const {
  const auto fail = [](const std::string& what) { throw std::invalid_argument(what); };
  if (population < 2) fail("population must be at least 2 (got " + std::to_string(population) + ")");
  if (evaluations < 1) fail("evaluations must be at least 1 (got " + std::to_string(evaluations) + ")");
  if (elites < 1 || elites >= population)
    fail("elites must be between 1 and population - 1 = " + std::to_string(population - 1) + " (got " +
         std::to_string(elites) + ")");
  if (!(mutation_sigma > 0.0) || !std::isfinite(mutation_sigma)) fail("mutation sigma must be a positive number");
  if (!(mutation_probability > 0.0 && mutation_probability <= 1.0)) fail("mutation probability must be in (0, 1]");
  if (!(weight_bound > 0.0) || !std::isfinite(weight_bound)) fail("weight bound must be a positive number");
  if (generations < 1) fail("generations must be at least 1 (got " + std::to_string(generations) + ")");
}

int generations_for_budget(std::int64_t budget, const Settings& settings) {
  const std::int64_t per_generation = settings.runs_per_generation();
  if (per_generation <= 0 || budget < per_generation)
    throw std::invalid_argument("a budget of " + std::to_string(budget) + " runs does not pay for one generation (" +
                                std::to_string(per_generation) + " runs: population x evaluations)");
  return static_cast<int>(std::min<std::int64_t>(budget / per_generation, 1'000'000'000));
}

std::uint64_t weight_digest(const arlequin::Weights& weights) {
  Fnv1a f;
  for (const double w : weights) f.add_u64(std::bit_cast<std::uint64_t>(w));
  return f.value();
}

Result evolve(const Mission& mission, Direction direction, Evaluator& evaluator, const Settings& settings,
              const Progress& progress, const Checkpoint* resume, const CheckpointSink& save, const StopRequest& stop) {
  settings.validate();
  Rng rng(settings.seed);
  std::vector<ControlSoftware> population;
  Result result;
  int first = 1;
  if (resume) {
    if (resume->generation < 0 || resume->generation >= settings.generations ||
        resume->population.size() != static_cast<std::size_t>(settings.population))
      throw std::invalid_argument("the saved evolution does not fit these settings");
    population.assign(resume->population.size(), network_software());
    for (std::size_t p = 0; p < population.size(); ++p) population[p].network.weights = resume->population[p];
    rng.set_state(resume->rng);
    result = resume->result;
    first = resume->generation + 1;
  } else {
    population = initial_population(settings, rng);
  }
  const auto size = population.size();
  auto save_state = [&](int done) {
    if (!save) return;
    Checkpoint checkpoint{done, {}, rng.state(), result};
    checkpoint.population.reserve(size);
    for (const ControlSoftware& network : population) checkpoint.population.push_back(network.network.weights);
    save(checkpoint);
  };
  if (!resume) save_state(0);
  const auto evaluations = static_cast<std::size_t>(settings.evaluations);
  std::vector<EvaluationTask> tasks(size * evaluations);
  std::vector<double> scores(tasks.size()), means(size);
  std::vector<std::size_t> ranking(size);

  for (int generation = first; generation <= settings.generations; ++generation) {
    std::vector<std::uint64_t> seeds(evaluations);
    for (auto& seed : seeds) seed = rng.next();
    for (std::size_t p = 0; p < size; ++p)
      for (std::size_t e = 0; e < evaluations; ++e) tasks[p * evaluations + e] = {&population[p], seeds[e]};
    evaluator.evaluate(mission, tasks, scores);
    result.runs += static_cast<std::int64_t>(tasks.size());

    for (std::size_t p = 0; p < size; ++p) {
      double sum = 0.0;
      for (std::size_t e = 0; e < evaluations; ++e) sum += scores[p * evaluations + e];
      means[p] = sum / static_cast<double>(evaluations);
    }
    std::iota(ranking.begin(), ranking.end(), std::size_t{0});
    std::stable_sort(ranking.begin(), ranking.end(), [&](std::size_t a, std::size_t b) {
      return direction == Direction::Maximize ? means[a] > means[b] : means[a] < means[b];
    });

    const ControlSoftware& best = population[ranking.front()];
    GenerationRecord record;
    record.generation = generation;
    record.best_mean = means[ranking.front()];
    record.population_mean = std::accumulate(means.begin(), means.end(), 0.0) / static_cast<double>(size);
    record.best_digest = weight_digest(best.network.weights);
    result.history.push_back(record);
    if (progress) progress(record);

    if (generation == settings.generations) {
      result.best = best.network.weights;
      result.best_mean = record.best_mean;
      break;
    }
    population = next_generation(population, ranking, settings, rng);
    save_state(generation);
    if (stop && stop()) {
      result.stopped = true;
      break;
    }
  }
  return result;
}

}  // namespace sd::evostick
