#pragma once
// The bridge from the optimiser to the simulator: a race step's experiments (configuration,
// seed) become evaluation tasks (control software, seed, key = configuration id) for whichever
// Evaluator the job runs on — threads here, MPI ranks or a server's pool elsewhere. Costs are
// the mission's scores, negated when the mission is maximised (irace minimises).
#include <algorithm>
#include <chrono>
#include <span>
#include <unordered_map>
#include <vector>

#include "control/control_software.hpp"
#include "design/experiment_runner.hpp"
#include "design/parameter_space.hpp"
#include "evaluation/evaluator.hpp"
#include "missions/mission.hpp"

namespace sd::app {

class SimulationRunner final : public design::ExperimentRunner {
 public:
  /// The mission, space, evaluator and models must outlive the runner. `instance_models`: a
  /// robust design's pseudo-realities, instance i running in model i; empty: every instance
  /// runs in the mission's own robot model.
  SimulationRunner(const Mission& mission, const design::ParameterSpace& space, Evaluator& evaluator,
                   std::span<const RobotModel> instance_models = {});

  void run(std::span<const design::Experiment> experiments, std::span<double> costs) override;

  /// Mission score of a cost.
  double score_of(double cost) const { return maximise_ ? -cost : cost; }
  /// Wall time spent inside run(), for the optimiser's overhead.
  double evaluation_seconds() const { return evaluation_seconds_; }
  int workers() const { return evaluator_.workers(); }
  std::size_t parallelism() const override { return static_cast<std::size_t>(std::max(1, evaluator_.workers())); }

 private:
  const Mission& mission_;
  const design::ParameterSpace& space_;
  Evaluator& evaluator_;
  std::span<const RobotModel> instance_models_;
  bool maximise_;
  // The control software of the configurations in the last batch: parsed once, kept at the
  // same address while the configuration races (the evaluator caches simulations by key).
  std::unordered_map<int, ControlSoftware> software_;
  std::vector<EvaluationTask> tasks_;
  std::vector<double> scores_;
  double evaluation_seconds_ = 0.0;
};

}  // namespace sd::app
