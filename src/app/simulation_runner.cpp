#include "cli/simulation_runner.hpp"

#include <algorithm>
#include <thread>
#include <unordered_set>

#include "control/config_string.hpp"
#include "evaluation/evaluator.hpp"

namespace sd::cli {

SimulationRunner::SimulationRunner(const Mission& mission, const design::ParameterSpace& space, unsigned threads)
    : mission_(mission),
      space_(space),
      maximise_(mission.objective.direction == Direction::Maximize),
      threads_(threads > 0 ? static_cast<int>(threads) : std::max(1, static_cast<int>(std::thread::hardware_concurrency()))),
      workers_(static_cast<std::size_t>(threads_)) {}

void SimulationRunner::run(std::span<const design::Experiment> experiments, std::span<double> costs) {
  const auto start = std::chrono::steady_clock::now();
  // Parse each configuration once, on this thread; keep only what this batch needs, so memory
  // follows the race, not the whole design.
  std::unordered_set<int> batch;
  for (const auto& e : experiments) {
    batch.insert(e.configuration_id);
    if (!software_.count(e.configuration_id))
      software_.emplace(e.configuration_id, parse_control_software(space_.render(*e.configuration)));
  }
  std::erase_if(software_, [&](const auto& entry) { return !batch.count(entry.first); });
  for (Cache& cache : workers_) std::erase_if(cache, [&](const auto& entry) { return !batch.count(entry.first); });

  parallel_for(experiments.size(), threads_, [&](std::size_t i, int worker) {
    const design::Experiment& e = experiments[i];
    auto& simulation = workers_[static_cast<std::size_t>(worker)][e.configuration_id];
    if (!simulation) simulation = std::make_unique<Simulation>(mission_, software_.at(e.configuration_id));
    const double score = simulation->run(e.seed);
    costs[i] = maximise_ ? -score : score;
  });
  evaluation_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace sd::cli
