#pragma once
// How a design's experiments are evaluated: every experiment of a race step simulated on
// T threads, each worker with its own Simulation per configuration, reused across seeds.
// Costs are written by index, and a simulation is a pure function of (mission, control
// software, seed), so the costs never depend on the thread count.
#include <chrono>
#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

#include "control/control_software.hpp"
#include "design/experiment_runner.hpp"
#include "design/parameter_space.hpp"
#include "evaluation/simulation.hpp"
#include "missions/mission.hpp"

namespace sd::cli {

class SimulationRunner final : public design::ExperimentRunner {
 public:
  /// `threads` 0: one per core. The mission and space must outlive the runner.
  SimulationRunner(const Mission& mission, const design::ParameterSpace& space, unsigned threads);

  /// cost = -score for a maximised objective, score for a minimised one.
  void run(std::span<const design::Experiment> experiments, std::span<double> costs) override;

  /// Mission score of a cost, and back.
  double score_of(double cost) const { return maximise_ ? -cost : cost; }
  /// Wall time spent inside run(), for the optimiser's overhead.
  double evaluation_seconds() const { return evaluation_seconds_; }
  int threads() const { return threads_; }

 private:
  using Cache = std::unordered_map<int, std::unique_ptr<Simulation>>;  // configuration id -> simulation

  const Mission& mission_;
  const design::ParameterSpace& space_;
  bool maximise_;
  int threads_;
  std::unordered_map<int, ControlSoftware> software_;  // of the configurations in the last batch
  std::vector<Cache> workers_;
  double evaluation_seconds_ = 0.0;
};

}  // namespace sd::cli
