#include "app/simulation_runner.hpp"

#include <unordered_set>

#include "control/config_string.hpp"

namespace sd::app {

SimulationRunner::SimulationRunner(const Mission& mission, const design::ParameterSpace& space, Evaluator& evaluator,
                                   std::span<const RobotModel> instance_models)
    : mission_(mission),
      space_(space),
      evaluator_(evaluator),
      instance_models_(instance_models),
      maximise_(mission.objective.direction == Direction::Maximize) {}

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

  tasks_.clear();
  for (const auto& e : experiments)
    tasks_.push_back({&software_.at(e.configuration_id), e.seed, e.configuration_id,
                      instance_models_.empty() ? nullptr : &instance_models_[e.instance]});
  scores_.resize(experiments.size());
  evaluator_.evaluate(mission_, tasks_, scores_);
  for (std::size_t i = 0; i < experiments.size(); ++i) costs[i] = maximise_ ? -scores_[i] : scores_[i];
  evaluation_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace sd::app
