// `swarmdesign evostick`: neuro-evolution of the Arlequin perceptron, either one Arlequin
// module against its training measure (--module) or the EvoStick baseline design method on a
// mission (--mission); --state FILE keeps its state at every generation and --resume FILE
// continues it after a kill. Settings and their defaults: src/evostick/evolution.hpp.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <optional>
#include <unistd.h>

#include "cli/command_registry.hpp"
#include "cli/design_run.hpp"
#include "cli/mission_input.hpp"
#include "cli/resumable_runs.hpp"
#include "control/config_string.hpp"
#include "evaluation/results_version.hpp"
#include "evostick/evolution.hpp"
#include "evostick/module_training.hpp"
#include "evostick/saved_evolution.hpp"
#include "evostick/weight_document.hpp"
#include "missions/catalogue.hpp"

namespace sd::cli {
namespace {

using nlohmann::json;

struct Options {
  std::string module, mission, output, state, resume;
  std::int64_t budget = 0;
  int threads = 0;
  bool json = false;
  evostick::Settings settings;
};

/// "\rgeneration 3/20: best mean ..., population mean ..." on stderr, when it is a terminal.
class ProgressLine {
 public:
  ProgressLine(bool enabled, int generations) : enabled_(enabled), generations_(generations) {}
  ~ProgressLine() {
    if (enabled_ && shown_) std::fprintf(stderr, "\r\033[K");
  }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;
  evostick::Progress callback() {
    if (!enabled_) return {};
    return [this](const evostick::GenerationRecord& r) {
      std::fprintf(stderr, "\r\033[Kgeneration %d/%d: best mean %s, population mean %s", r.generation, generations_,
                   format_number(r.best_mean).c_str(), format_number(r.population_mean).c_str());
      std::fflush(stderr);
      shown_ = true;
    };
  }

 private:
  bool enabled_;
  int generations_;
  bool shown_ = false;
};

void write_output(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  if (!out || !(out << text)) throw std::runtime_error("cannot write " + path);
}

ControlSoftware network(const arlequin::Weights& weights) {
  ControlSoftware software;
  software.architecture = Architecture::NeuralNetwork;
  software.network.weights = weights;
  return software;
}

void print_text(const evostick::Result& result, const evostick::Settings& settings) {
  std::cout << to_config_string(network(result.best)) << "\n"
            << "Mean " << format_number(result.best_mean) << "\n"
            << "Runs " << result.runs << "\n"
            << "Generations " << settings.generations << "\n";
}

/// Where the evolution's state goes after every generation (--state, or the file resumed from),
/// and the state it continues from.
struct Persistence {
  evostick::EvolutionTarget target;
  std::filesystem::path file;  // empty: the state is not kept
  std::optional<evostick::Checkpoint> resume;

  evostick::CheckpointSink sink() const {
    if (file.empty()) return {};
    return [this](const evostick::Checkpoint& c) { evostick::write_saved_evolution(file, target, c); };
  }
  const evostick::Checkpoint* from() const { return resume ? &*resume : nullptr; }
};

void run_module(const Options& o, const Persistence& keep) {
  const evostick::ModuleTraining* module = evostick::find_module_training(o.module);
  if (!module)
    throw UsageError("--module: unknown module '" + o.module + "' (one of " + evostick::module_names_text() + ")");
  const bool progress_shown = isatty(STDERR_FILENO) && !o.json;
  ProgressLine line(progress_shown, o.settings.generations);
  const evostick::Result result =
      evostick::train_module(*module, o.settings, o.threads, line.callback(), keep.from(), keep.sink());
  const std::string text = evostick::document_text(evostick::module_document(*module, o.settings, result));
  if (!o.output.empty()) write_output(o.output, text);
  if (o.json) {
    std::cout << text;
    return;
  }
  print_text(result, o.settings);
  std::cout << "Measure " << evostick::measure_name(module->measure) << " (maximised)\n";
  if (!o.output.empty()) std::cout << "Written to " << o.output << "\n";
}

void run_mission(const Options& o, const Mission& mission, const Persistence& keep) {
  const bool progress_shown = isatty(STDERR_FILENO) && !o.json;
  ProgressLine line(progress_shown, o.settings.generations);
  ThreadedEvaluator evaluator(o.threads);
  const evostick::Result result = evostick::evolve(mission, mission.objective.direction, evaluator, o.settings,
                                                   line.callback(), keep.from(), keep.sink());
  json doc{{"mission", mission.name},
           {"direction", direction_name(mission.objective.direction)},
           {"settings", evostick::settings_json(o.settings)},
           {"runs", result.runs},
           {"control_software", to_config_string(network(result.best))},
           {"mean", result.best_mean},
           {"weights_digest", evostick::digest_text(evostick::weight_digest(result.best))},
           {"history", evostick::history_json(result.history)},
           {"weights", evostick::weights_json(result.best)}};
  if (o.budget > 0) doc["budget"] = o.budget;
  const std::string text = evostick::document_text(doc);
  if (!o.output.empty()) write_output(o.output, text);
  if (o.json) {
    std::cout << text;
    return;
  }
  print_text(result, o.settings);
  if (!o.output.empty()) std::cout << "Written to " << o.output << "\n";
}

void resume_evolution(Options o) {
  evostick::SavedEvolution saved = evostick::read_saved_evolution(o.resume);
  const evostick::EvolutionTarget& target = saved.target;
  const std::string what = "the evolution in " + o.resume;
  if (const std::string refusal = results_version_refusal(what, target.results_version); !refusal.empty())
    throw std::runtime_error(refusal);  // first: a module has no mission file to check
  o.settings = target.settings;
  try {
    o.settings.validate();
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(o.resume + " is a damaged EvoStick state file (" + e.what() + ")");
  }
  const Persistence keep{target, o.resume, std::move(saved.checkpoint)};
  if (!target.module.empty()) {
    o.module = target.module;
    run_module(o, keep);
  } else {
    const ResumeCheck check = check_resumable(what, target.mission, target.mission_digest, target.results_version);
    if (!check.refusal.empty()) throw std::runtime_error(check.refusal);
    run_mission(o, check.mission, keep);
  }
}

void start_evolution(const Options& o) {
  Persistence keep;
  keep.file = o.state;
  keep.target.settings = o.settings;
  keep.target.results_version = kResultsVersion;
  if (!o.state.empty() && std::filesystem::exists(o.state))
    throw UsageError("--state: " + o.state + " already holds an evolution; continue it with --resume " + o.state);
  if (!o.module.empty()) {
    keep.target.module = o.module;
    run_module(o, keep);
    return;
  }
  const Mission mission = load_mission_or_usage(o.mission);
  keep.target.mission = mission_reference(o.mission);
  keep.target.mission_digest = mission.digest;
  run_mission(o, mission, keep);
}

void register_evostick(CLI::App& app, Context& context) {
  auto* cmd = app.add_subcommand(
      "evostick", "Evolve an Arlequin network: one module (--module) or the EvoStick baseline on a mission (--mission)");
  auto o = std::make_shared<Options>();
  auto* module = cmd->add_option("--module", o->module,
                                 "Train an Arlequin module against its measure: " + evostick::module_names_text());
  auto* mission = cmd->add_option("--mission", o->mission, "Design a network for this mission (name or file)");
  module->excludes(mission);
  auto* seed = cmd->add_option("--seed", o->settings.seed, "Seed of the evolution (default 1)");
  auto* generations = cmd->add_option("--generations", o->settings.generations,
                                      "Generations (--module default: " +
                                          std::to_string(evostick::kShippedGenerations) + ", the shipped weights')");
  auto* budget = cmd->add_option("--budget", o->budget,
                                 "Budget in simulation runs; generations = budget / (population x evaluations)");
  generations->excludes(budget);
  auto* population = cmd->add_option("--population", o->settings.population, "Networks per generation (default 100)");
  auto* evaluations =
      cmd->add_option("--evaluations", o->settings.evaluations, "Runs per network and generation (default 10)");
  auto* elites = cmd->add_option("--elites", o->settings.elites, "Best networks kept unchanged (default 20)");
  auto* sigma =
      cmd->add_option("--mutation-sigma", o->settings.mutation_sigma, "Standard deviation of the weight noise (default 1)");
  auto* probability = cmd->add_option("--mutation-probability", o->settings.mutation_probability,
                                      "Chance that each weight of a child gets noise (default 0.3)");
  auto* state = cmd->add_option("--state", o->state,
                                "Keep the evolution's state in FILE at every generation; after a kill, --resume FILE "
                                "continues it");
  cmd->add_option("--resume", o->resume,
                  "Continue the evolution kept in FILE (--state) with its mission or module and settings, and keep "
                  "its state there");
  cmd->add_option("--threads", o->threads, "Worker threads (default: all cores); never changes the result")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--output", o->output, "Also write the JSON document to FILE");
  cmd->add_flag("--json", o->json, "Print one JSON document (for --module: the format of data/arlequin/*.json)");
  cmd->footer(
      "Weights stay in [-5, 5]. Prints the best network's --nn-config string, its mean score over the last\n"
      "generation's runs, and the runs used. The same seed and settings give the same network whatever --threads.\n"
      "Examples:\n"
      "  swarmdesign evostick --module phototaxis --seed 1 --output data/arlequin/phototaxis.json\n"
      "  swarmdesign evostick --mission aac --budget 20000 --seed 7 --json --state aac-7.evostick\n"
      "  swarmdesign evostick --resume aac-7.evostick --json");
  const std::vector<const CLI::Option*> settings_options{module,      mission, seed,  generations, budget,     population,
                                                         evaluations, elites,  sigma, probability, state};
  cmd->callback([o, module, mission, generations, budget, settings_options, &context] {
    if (context.has_control_software()) throw UsageError("evostick takes no control software: it evolves one");
    if (!o->resume.empty()) {
      for (const CLI::Option* option : settings_options)
        if (option->count() > 0)
          throw UsageError("--resume continues with what " + o->resume + " keeps; " + option->get_name() +
                           " cannot change it");
      resume_evolution(*o);
      return;
    }
    if (module->count() == 0 && mission->count() == 0) throw UsageError("give --module NAME, --mission M or --resume FILE");
    if (mission->count() > 0 && generations->count() == 0 && budget->count() == 0)
      throw UsageError("--mission needs a budget: --budget RUNS or --generations G");
    if (module->count() > 0 && generations->count() == 0 && budget->count() == 0)
      o->settings.generations = evostick::kShippedGenerations;
    try {
      if (budget->count() > 0) o->settings.generations = evostick::generations_for_budget(o->budget, o->settings);
      o->settings.validate();
    } catch (const std::invalid_argument& e) {
      throw UsageError(e.what());
    }
    start_evolution(*o);
  });
}

const CommandRegistrar registrar{30, [](CLI::App& app, Context& context) { register_evostick(app, context); }};

}  // namespace
}  // namespace sd::cli
