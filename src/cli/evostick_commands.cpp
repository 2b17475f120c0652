// `swarmdesign evostick`: neuro-evolution of the Arlequin perceptron, either one Arlequin
// module against its training measure (--module) or the EvoStick baseline design method on a
// mission (--mission). Settings and their defaults: src/evostick/evolution.hpp.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <unistd.h>

#include "cli/command_registry.hpp"
#include "cli/mission_input.hpp"
#include "control/config_string.hpp"
#include "evostick/evolution.hpp"
#include "evostick/module_training.hpp"
#include "evostick/weight_document.hpp"
#include "missions/catalogue.hpp"

namespace sd::cli {
namespace {

using nlohmann::json;

struct Options {
  std::string module, mission, output;
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

void run_module(const Options& o) {
  const evostick::ModuleTraining* module = evostick::find_module_training(o.module);
  if (!module)
    throw UsageError("--module: unknown module '" + o.module + "' (one of " + evostick::module_names_text() + ")");
  const bool progress_shown = isatty(STDERR_FILENO) && !o.json;
  ProgressLine line(progress_shown, o.settings.generations);
  const evostick::Result result = evostick::train_module(*module, o.settings, o.threads, line.callback());
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

void run_mission(const Options& o) {
  const Mission mission = load_mission_or_usage(o.mission);
  const bool progress_shown = isatty(STDERR_FILENO) && !o.json;
  ProgressLine line(progress_shown, o.settings.generations);
  ThreadedEvaluator evaluator(o.threads);
  const evostick::Result result =
      evostick::evolve(mission, mission.objective.direction, evaluator, o.settings, line.callback());
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

void register_evostick(CLI::App& app, Context& context) {
  auto* cmd = app.add_subcommand(
      "evostick", "Evolve an Arlequin network: one module (--module) or the EvoStick baseline on a mission (--mission)");
  auto o = std::make_shared<Options>();
  auto* module = cmd->add_option("--module", o->module,
                                 "Train an Arlequin module against its measure: " + evostick::module_names_text());
  auto* mission = cmd->add_option("--mission", o->mission, "Design a network for this mission (name or file)");
  module->excludes(mission);
  cmd->add_option("--seed", o->settings.seed, "Seed of the evolution (default 1)");
  auto* generations = cmd->add_option("--generations", o->settings.generations,
                                      "Generations (--module default: " +
                                          std::to_string(evostick::kShippedGenerations) + ", the shipped weights')");
  auto* budget = cmd->add_option("--budget", o->budget,
                                 "Budget in simulation runs; generations = budget / (population x evaluations)");
  generations->excludes(budget);
  cmd->add_option("--population", o->settings.population, "Networks per generation (default 100)");
  cmd->add_option("--evaluations", o->settings.evaluations, "Runs per network and generation (default 10)");
  cmd->add_option("--elites", o->settings.elites, "Best networks kept unchanged (default 20)");
  cmd->add_option("--mutation-sigma", o->settings.mutation_sigma, "Standard deviation of the weight noise (default 1)");
  cmd->add_option("--mutation-probability", o->settings.mutation_probability,
                  "Chance that each weight of a child gets noise (default 0.3)");
  cmd->add_option("--threads", o->threads, "Worker threads (default: all cores); never changes the result")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--output", o->output, "Also write the JSON document to FILE");
  cmd->add_flag("--json", o->json, "Print one JSON document (for --module: the format of data/arlequin/*.json)");
  cmd->footer(
      "Weights stay in [-5, 5]. Prints the best network's --nn-config string, its mean score over the last\n"
      "generation's runs, and the runs used. The same seed and settings give the same network whatever --threads.\n"
      "Examples:\n"
      "  swarmdesign evostick --module phototaxis --seed 1 --output data/arlequin/phototaxis.json\n"
      "  swarmdesign evostick --mission aac --budget 20000 --seed 7 --json");
  cmd->callback([o, module, mission, generations, budget, &context] {
    if (context.has_control_software()) throw UsageError("evostick takes no control software: it evolves one");
    if (module->count() == 0 && mission->count() == 0) throw UsageError("give --module NAME or --mission M");
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
    if (module->count() > 0) run_module(*o);
    else run_mission(*o);
  });
}

const CommandRegistrar registrar{30, [](CLI::App& app, Context& context) { register_evostick(app, context); }};

}  // namespace
}  // namespace sd::cli
