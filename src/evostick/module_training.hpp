#pragma once
// Training the six Arlequin modules with EvoStick: each module has a training arena
// (data/arlequin/training/*.json, compiled in) and a measure (training_measures.hpp) that
// rewards what the module is named after. `swarmdesign evostick --module NAME` with the
// shipped seed and generations writes exactly the shipped data/arlequin/NAME.json.
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "evaluation/evaluator.hpp"
#include "evostick/evolution.hpp"
#include "evostick/training_measures.hpp"

namespace sd::evostick {

struct ModuleTraining {
  int id;                  // 50-55
  std::string_view name;   // arlequin::kModuleNames
  std::string_view arena;  // data/arlequin/training/<arena>.json
  Measure measure;
};

/// The six modules in id order.
const std::array<ModuleTraining, 6>& module_trainings();
const ModuleTraining* find_module_training(std::string_view name);
/// "exploration, stop, ..." for messages.
std::string module_names_text();

/// The module's training arena as a mission (its own objective is not what EvoStick scores).
Mission training_mission(const ModuleTraining& module);

/// The settings the shipped weights were produced with: the EvoStick defaults, this seed and
/// this many generations (see data/arlequin/README.md for why so few).
inline constexpr std::uint64_t kShippedSeed = 1;
inline constexpr int kShippedGenerations = 20;
Settings shipped_settings();

/// Scores runs with a training measure instead of the mission's objective, on local threads of
/// the process's Executor; scores by task index, like every Evaluator.
class MeasureEvaluator : public Evaluator {
 public:
  MeasureEvaluator(Measure measure, int threads = 0);
  void evaluate(const Mission& mission, std::span<const EvaluationTask> tasks, std::span<double> scores) override;
  int workers() const override { return threads_; }

 private:
  Measure measure_;
  int threads_;
};

/// Evolves one module's network.
Result train_module(const ModuleTraining& module, const Settings& settings, int threads, const Progress& progress = {},
                    const Checkpoint* resume = nullptr, const CheckpointSink& save = {}, const StopRequest& stop = {});

}  // namespace sd::evostick
