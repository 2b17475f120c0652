#include "app/evolution_job.hpp"

#include <filesystem>
#include <fstream>

#include "app/documents/evolution.hpp"
#include "app/errors.hpp"
#include "app/inputs.hpp"
#include "app/user_files.hpp"
#include "app/resume_check.hpp"
#include "control/config_string.hpp"
#include "evaluation/evaluator.hpp"
#include "evaluation/results_version.hpp"
#include "evostick/module_training.hpp"
#include "evostick/saved_evolution.hpp"
#include "evostick/weight_document.hpp"
#include "missions/catalogue.hpp"

namespace sd::app {

namespace {

evostick::Progress progress_of(const EvolutionRun& run, const evostick::Settings& settings) {
  if (!run.progress) return {};
  return [&run, generations = settings.generations](const evostick::GenerationRecord& r) { run.progress(r, generations); };
}

/// Where the evolution's state goes after every generation, and the state it continues from.
struct Persistence {
  evostick::EvolutionTarget target;
  std::filesystem::path file;  // empty: the state is not kept
  std::optional<evostick::Checkpoint> resume;
  std::function<void(int)> saved;

  evostick::CheckpointSink sink() const {
    if (file.empty()) return {};
    return [this](const evostick::Checkpoint& c) {
      evostick::write_saved_evolution(file, target, c);
      if (saved) saved(c.generation);
    };
  }
  const evostick::Checkpoint* from() const { return resume ? &*resume : nullptr; }
};

evostick::StopRequest stop_of(const EvolutionRun& run) {
  if (!run.cancel) return {};
  return [token = run.cancel] { return token->cancelled(); };
}

void write_output(const std::string& path, const std::string& text) {
  if (path.empty()) return;
  std::ofstream out(path);
  if (!out || !(out << text)) throw std::runtime_error("cannot write " + path);
}

std::string network_config(const arlequin::Weights& weights) {
  ControlSoftware software;
  software.architecture = Architecture::NeuralNetwork;
  software.network.weights = weights;
  return to_config_string(software);
}

EvolutionOutcome run_module(const std::string& name, const evostick::Settings& settings, const std::string& output,
                            const EvolutionRun& run, const Persistence& keep) {
  const evostick::ModuleTraining* module = evostick::find_module_training(name);
  if (!module)
    throw InvalidRequest("unknown module '" + name + "' (one of " + evostick::module_names_text() + ")");
  EvolutionOutcome out;
  out.result = evostick::train_module(*module, settings, run.threads, progress_of(run, settings), keep.from(), keep.sink(),
                                      stop_of(run));
  out.settings = settings;
  if ((out.cancelled = out.result.stopped)) return out;
  out.module = name;
  out.measure = evostick::measure_name(module->measure);
  out.control_software = network_config(out.result.best);
  out.document = evostick::document_text(evostick::module_document(*module, settings, out.result));
  write_output(output, out.document);
  return out;
}

EvolutionOutcome run_mission(const Mission& mission, const evostick::Settings& settings, std::int64_t budget,
                             const std::string& output, const EvolutionRun& run, const Persistence& keep) {
  const std::unique_ptr<Evaluator> backend = make_evaluator(run.threads);
  Evaluator& evaluator = *backend;
  EvolutionOutcome out;
  out.result = evostick::evolve(mission, mission.objective.direction, evaluator, settings, progress_of(run, settings),
                                keep.from(), keep.sink(), stop_of(run));
  out.settings = settings;
  if ((out.cancelled = out.result.stopped)) return out;
  out.control_software = network_config(out.result.best);
  out.document = evostick::document_text(mission_evolution_document(mission, settings, out.result, out.control_software, budget));
  write_output(output, out.document);
  return out;
}

}  // namespace

EvolutionOutcome start_evolution(const EvolutionRequest& request, const EvolutionRun& run) {
  evostick::Settings settings = request.settings;
  try {
    if (request.budget > 0) settings.generations = evostick::generations_for_budget(request.budget, settings);
    settings.validate();
  } catch (const std::invalid_argument& e) {
    throw InvalidRequest(e.what());
  }
  if (!request.state.empty() && std::filesystem::exists(request.state))
    throw InvalidRequest("--state: " + request.state + " already holds an evolution; continue it with --resume " +
                         request.state);
  Persistence keep;
  keep.file = request.state;
  keep.saved = run.saved;
  keep.target.settings = settings;
  keep.target.results_version = kResultsVersion;
  if (!request.module.empty()) {
    keep.target.module = request.module;
    return run_module(request.module, settings, request.output, run, keep);
  }
  const Mission mission = load_requested_mission(request.mission);
  keep.target.mission = mission_reference(request.mission);
  keep.target.mission_digest = mission.digest;
  return run_mission(mission, settings, request.budget, request.output, run, keep);
}

EvolutionOutcome resume_evolution(const std::string& file, const EvolutionRun& run, const std::string& output) {
  evostick::SavedEvolution saved = evostick::read_saved_evolution(file);
  const evostick::EvolutionTarget& target = saved.target;
  const std::string what = "the evolution in " + file;
  if (!target.module.empty()) {  // a module has no mission file to check, only its training arena
    const evostick::ModuleTraining* module = evostick::find_module_training(target.module);
    const int robots = module ? evostick::training_mission(*module).robots : 0;  // unknown: run_module says so
    if (const std::string refusal = results_version_refusal(what, target.results_version, robots); !refusal.empty())
      throw DesignFolderError(refusal);
  }
  evostick::Settings settings = target.settings;
  try {
    settings.validate();
  } catch (const std::invalid_argument& e) {
    throw DesignFolderError(file + " is a damaged EvoStick state file (" + e.what() + ")");
  }
  const Persistence keep{target, file, std::move(saved.checkpoint), run.saved};
  if (!target.module.empty()) return run_module(target.module, settings, output, run, keep);
  const ResumeCheck check = check_resumable(what, target.mission, target.mission_digest, target.results_version);
  if (!check.refusal.empty()) throw DesignFolderError(check.refusal);
  return run_mission(check.mission, settings, 0, output, run, keep);
}

}  // namespace sd::app
