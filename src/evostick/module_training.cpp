#include "evostick/module_training.hpp"

#include <stdexcept>

#include "core/executor.hpp"
#include "evaluation/simulation.hpp"
#include "evostick/builtin_training_arenas.hpp"

namespace sd::evostick {

const std::array<ModuleTraining, 6>& module_trainings() {
  // Attraction and repulsion train where every cue comes in a symmetric pair, so that only
  // the neighbours can gather or spread the swarm (data/arlequin/training/*.json).
  static const std::array<ModuleTraining, 6> table = {{
      {50, arlequin::kModuleNames[0], "cues", Measure::Coverage},
      {51, arlequin::kModuleNames[1], "cues", Measure::Stillness},
      {52, arlequin::kModuleNames[2], "cues", Measure::LightApproach},
      {53, arlequin::kModuleNames[3], "cues", Measure::LightAvoidance},
      {54, arlequin::kModuleNames[4], "symmetric-cues", Measure::Cohesion},
      {55, arlequin::kModuleNames[5], "symmetric-cues", Measure::Dispersion},
  }};
  return table;
}

const ModuleTraining* find_module_training(std::string_view name) {
  for (const ModuleTraining& m : module_trainings())
    if (m.name == name) return &m;
  return nullptr;
}

std::string module_names_text() {
  std::string text;
  for (const ModuleTraining& m : module_trainings()) text += (text.empty() ? "" : ", ") + std::string(m.name);
  return text;
}

Mission training_mission(const ModuleTraining& module) {
  for (const BuiltinTrainingArena& arena : builtin_training_arenas())
    if (arena.name == module.arena) return parse_mission(std::string(arena.json), "built-in");
  throw std::runtime_error("the build carries no data/arlequin/training/" + std::string(module.arena) + ".json");
}

Settings shipped_settings() {
  Settings settings;
  settings.seed = kShippedSeed;
  settings.generations = kShippedGenerations;
  return settings;
}

MeasureEvaluator::MeasureEvaluator(Measure measure, int threads)
    : measure_(measure), threads_(resolve_threads(threads)) {}

void MeasureEvaluator::evaluate(const Mission& mission, std::span<const EvaluationTask> tasks, std::span<double> scores) {
  // A fresh simulation per run: building one costs far less than its 400 ticks, and a run's
  // result does not depend on whether its Simulation was reused (evaluation/simulation.hpp).
  Executor::shared().run(tasks.size(), static_cast<unsigned>(threads_), [&](std::size_t i, unsigned) {
    Simulation simulation(mission, *tasks[i].software);
    MeasureObserver observer(measure_, mission);
    simulation.run(tasks[i].seed, &observer);
    scores[i] = observer.value();
  });
}

Result train_module(const ModuleTraining& module, const Settings& settings, int threads, const Progress& progress,
                    const Checkpoint* resume, const CheckpointSink& save, const StopRequest& stop) {
  const Mission mission = training_mission(module);
  MeasureEvaluator evaluator(module.measure, threads);
  return evolve(mission, Direction::Maximize, evaluator, settings, progress, resume, save, stop);
}

}  // namespace sd::evostick
