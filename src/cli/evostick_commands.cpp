// `swarmdesign evostick`: neuro-evolution of the Arlequin perceptron, either one Arlequin
// module against its training measure (--module) or the EvoStick baseline design method on a
// mission (--mission); --state FILE keeps its state at every generation and --resume FILE
// continues it after a kill. Settings and their defaults: src/evostick/evolution.hpp.
#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>

#include "app/evolution_job.hpp"
#include "app/inputs.hpp"
#include "cli/command_registry.hpp"
#include "cli/fault_injection.hpp"
#include "cli/progress_line.hpp"
#include "control/config_string.hpp"
#include "evostick/module_training.hpp"

namespace sd::cli::evostick_commands {
namespace {

struct Options {
  // The seed is text for app::parse_seed: CLI11 would read "-1" as 2^64-1.
  std::string module, mission, output, state, resume, budget, seed;
  int threads = 0;
  bool json = false;
  evostick::Settings settings;
};

void print(const app::EvolutionOutcome& out, const Options& o) {
  if (o.json) {
    std::cout << out.document;
    return;
  }
  std::cout << out.control_software << "\n"
            << "Mean " << format_number(out.result.best_mean) << "\n"
            << "Runs " << out.result.runs << "\n"
            << "Generations " << out.settings.generations << "\n";
  if (!out.measure.empty()) std::cout << "Measure " << out.measure << " (maximised)\n";
  if (!o.output.empty()) std::cout << "Written to " << o.output << "\n";
}

/// Runs the evolution with "generation 3/20: best mean ..." on a terminal.
template <class Job>
void run_with_progress(const Options& o, Job job) {
  ProgressLine line(ProgressLine::terminal_if(!o.json));
  app::EvolutionRun run{o.threads, {}, {}};
  if (kill_at_checkpoint() > 0) run.saved = [](int generation) { kill_if_checkpoint(generation); };
  if (line.mode() != ProgressLine::Mode::Off)
    run.progress = [&](const evostick::GenerationRecord& r, int generations) {
      line.show("generation " + std::to_string(r.generation) + "/" + std::to_string(generations) + ": best mean " +
                format_number(r.best_mean) + ", population mean " + format_number(r.population_mean));
    };
  const app::EvolutionOutcome out = job(run);
  line.clear();
  print(out, o);
}

void register_evostick(CLI::App& app, Context& context) {
  auto* cmd = app.add_subcommand(
      "evostick", "Evolve an Arlequin network: one module (--module) or the EvoStick baseline on a mission (--mission)");
  auto o = std::make_shared<Options>();
  auto* module = cmd->add_option("--module", o->module,
                                 "Train an Arlequin module against its measure: " + evostick::module_names_text());
  auto* mission = cmd->add_option("--mission", o->mission, "Design a network for this mission (name or file)");
  module->excludes(mission);
  auto* seed = cmd->add_option("--seed", o->seed, "Seed of the evolution (default 1)");
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
      run_with_progress(*o, [&](const app::EvolutionRun& run) { return app::resume_evolution(o->resume, run, o->output); });
      return;
    }
    if (module->count() == 0 && mission->count() == 0) throw UsageError("give --module NAME, --mission M or --resume FILE");
    if (mission->count() > 0 && generations->count() == 0 && budget->count() == 0)
      throw UsageError("--mission needs a budget: --budget RUNS or --generations G");
    if (module->count() > 0 && generations->count() == 0 && budget->count() == 0)
      o->settings.generations = evostick::kShippedGenerations;
    if (!o->seed.empty()) o->settings.seed = app::parse_seed(o->seed);
    app::EvolutionRequest request{o->module, o->mission, o->settings, 0, o->state, o->output};
    if (budget->count() > 0) request.budget = app::parse_budget(o->budget);
    run_with_progress(*o, [&](const app::EvolutionRun& run) { return app::start_evolution(request, run); });
  });
}

const CommandRegistrar registrar{30, [](CLI::App& app, Context& context) { register_evostick(app, context); }};

}  // namespace
}  // namespace sd::cli::evostick_commands
