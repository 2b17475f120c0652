// Designing without an account: `design` (run or resume a design process in a folder),
// `design-status` (where a design folder stands; a cluster project asks it of its jobs) and
// `irace-export` (let the real irace 3.5 drive SwarmDesign's evaluator).
#include <nlohmann/json.hpp>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>

#include "app/design_job.hpp"
#include "app/documents.hpp"
#include "app/inputs.hpp"
#include "app/irace_export_job.hpp"
#include "cli/command_registry.hpp"
#include "cli/design_display.hpp"
#include "cli/design_flags.hpp"
#include "control/config_string.hpp"
#include "storage/design_status.hpp"

namespace sd::cli::design_commands {
namespace {

struct DesignOptions {
  std::string mission, budget, seed, out, resume, method;
  unsigned threads = 0;
  bool json = false;
  DesignSpaceFlags flags;
  RobustDesignFlags robust;
};

void run_design_command(const DesignOptions& o) {
  app::PreparedDesign prepared;
  if (!o.resume.empty()) {
    if (!o.mission.empty() || !o.budget.empty() || !o.seed.empty() || !o.out.empty() || !o.method.empty() || o.flags.any() ||
        o.robust.any())
      throw UsageError("--resume continues a design with the settings it was started with; give only --threads or --json with it");
    prepared = app::prepare_resume(o.resume, true);  // a finished one: its result, as run-design gives it
  } else {
    if (o.mission.empty()) throw UsageError("--mission is required (or --resume DIR)");
    if (o.budget.empty()) throw UsageError("--budget is required (or --resume DIR)");
    app::NewDesignSettings settings;
    settings.mission = o.mission;
    settings.budget = app::parse_budget(o.budget);
    settings.space = o.flags.request();
    if (!o.method.empty()) settings.method = &app::search_method(o.method);
    settings.seed = o.seed.empty() ? app::random_seed() : app::parse_seed(o.seed);
    if (o.robust.samples.size() && o.robust.pseudo_realities.empty())
      throw UsageError("--pseudo-reality-samples needs --pseudo-reality SPEC");
    settings.pseudo_reality = o.robust.pseudo_realities;
    if (!o.robust.samples.empty()) settings.pseudo_reality_samples = o.robust.samples;
    prepared = app::prepare_design_in(settings, o.out);
  }
  for (const auto& note : prepared.choice.notes) std::cerr << "swarmdesign: note: " << note << "\n";
  if (!o.json)
    std::cout << (app::already_finished(prepared) ? "The design in " + prepared.folder.string() + " has already finished"
                  : (prepared.resuming ? "Resuming the design in " : "Designing in ") + prepared.folder.string())
              << " (mission " << prepared.mission.name
              << (prepared.method != &design::kAutoMoDe ? ", method " + std::string(prepared.method->name) : "")
              << ", budget " << prepared.options.max_experiments
              << ", seed " << prepared.options.seed
              << (prepared.reality ? ", robust: pseudo-realities " + prepared.reality->reference + " samples " + prepared.reality_samples : "")
              << ")\n"
              << std::flush;
  DesignDisplay display(ProgressLine::terminal_if(!o.json), prepared.mission.objective.direction == Direction::Maximize);
  const app::DesignOutcome outcome = app::run_design(prepared, {.threads = o.threads, .observer = &display});
  display.finish();
  if (o.json) std::cout << app::design_report_document(*outcome.report).dump(2) << "\n";
  else print_design_report(*outcome.report);
}

/// One line per method with a design space, for the help text.
std::string method_lines() {
  std::string text = "Methods (--method):\n";
  for (const design::MethodInfo* m : design::kMethods)
    if (m->has_design_space) text += "  " + std::string(m->name) + std::string(std::max<std::size_t>(15, m->name.size() + 1) - m->name.size(), ' ') + std::string(m->summary) + "\n";
  return text;
}

void register_design(CLI::App& app) {
  auto* cmd = app.add_subcommand("design", "Design control software for a mission (Iterated F-Race unless --method says)");
  auto o = std::make_shared<DesignOptions>();
  cmd->add_option("--mission", o->mission, "Mission name or mission file");
  cmd->add_option("--budget", o->budget, "Design budget: the number of simulation runs the optimiser may use");
  cmd->add_option("--method", o->method, "Optimiser over the design space: " + app::search_method_names() + " (default automode)");
  add_design_space_flags(*cmd, o->flags);
  add_robust_design_flags(*cmd, o->robust);
  cmd->add_option("--seed", o->seed, "Seed of the design (default: a random one, printed); same seed, same result");
  cmd->add_option("--threads", o->threads, "Simulations in parallel (default: all cores); the result does not depend on it")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--out", o->out, "Folder of the design (default: ./design-<mission>-seed<S>)");
  cmd->add_option("--resume", o->resume, "Continue the design kept in DIR (after it was interrupted or killed)");
  cmd->add_flag("--json", o->json, "Print the final report as one JSON document");
  cmd->footer(
      "Architecture flags: --fsm, --bt (none = all that exist). Flavour flags: --chocolate, --tuttifrutti,\n"
      "--coconut, --maple, --arlequin (none = all that exist). The design keeps its whole state in\n"
      "DIR/design.db after every race step, so a killed design continues with --resume DIR and ends\n"
      "exactly as if it had never stopped.\n\n" +
      method_lines() + "\n"
      "Example:\n  swarmdesign design --mission aac --budget 20000 --fsm --chocolate --seed 1 --out aac-1\n"
      "  swarmdesign design --resume aac-1\n"
      "  swarmdesign design --mission aac --budget 20000 --fsm --chocolate --pseudo-reality sampled-around --out aac-robust");
  cmd->callback([o] { run_design_command(*o); });
}

struct ExportOptions {
  std::string mission, budget = "5000", seed, out;
  int iterations = 0;
  DesignSpaceFlags flags;
};

void run_irace_export(const ExportOptions& o) {
  app::IraceExportRequest request;
  request.mission = o.mission;
  request.space = o.flags.request();
  request.budget = app::parse_budget(o.budget);
  request.seed = o.seed.empty() ? 0 : app::parse_seed(o.seed);
  request.iterations = o.iterations;
  request.out = o.out;
  request.executable = std::filesystem::read_symlink("/proc/self/exe").string();
  for (const auto& note : app::export_irace(request)) std::cerr << "swarmdesign: note: " << note << "\n";
  std::cout << "Wrote parameters.txt, scenario.txt, instances.txt and target-runner to " << o.out << ".\n"
            << "Run irace 3.5 with:\n  cd " << o.out
            << " && Rscript -e 'irace::irace.cmdline(c(\"--scenario\", \"scenario.txt\"))'\n";
}

void register_irace_export(CLI::App& app) {
  auto* cmd = app.add_subcommand("irace-export", "Write the files with which irace 3.5 drives SwarmDesign's evaluator");
  auto o = std::make_shared<ExportOptions>();
  cmd->add_option("--mission", o->mission, "Mission name or mission file")->required();
  add_design_space_flags(*cmd, o->flags);
  cmd->add_option("--out", o->out, "Folder to write parameters.txt, scenario.txt, instances.txt, target-runner")
      ->required();
  cmd->add_option("--budget", o->budget,
                  "maxExperiments of the scenario (default 5000); at least irace's minimum for the design space");
  cmd->add_option("--seed", o->seed, "irace's seed (default: irace picks one)");
  cmd->add_option("--iterations", o->iterations, "nbIterations of the scenario (default: irace's own)")
      ->check(CLI::PositiveNumber);
  cmd->footer(
      "target-runner calls this swarmdesign's `evaluate` and prints the cost (the score, negated for\n"
      "missions that are maximised); set $SWARMDESIGN to use another executable.\n\n"
      "Example:\n  swarmdesign irace-export --mission aac --fsm --chocolate --budget 20000 --out aac-irace\n"
      "  cd aac-irace && Rscript -e 'irace::irace.cmdline(c(\"--scenario\", \"scenario.txt\"))'");
  cmd->callback([o] { run_irace_export(*o); });
}

void register_design_status(CLI::App& app) {
  struct Options {
    std::string folder;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  auto* cmd = app.add_subcommand("design-status", "Show where the design in a folder stands (also while it runs)");
  cmd->add_option("DIR", o->folder, "the design's folder (design --out DIR)")->required();
  cmd->add_flag("--json", o->json, "Print one JSON document");
  cmd->footer("Example:\n  swarmdesign design-status design-aac-seed1 --json");
  cmd->callback([o] {
    const storage::DesignProgress p = storage::read_design_progress(o->folder);
    if (o->json) {
      std::cout << app::stored_progress_document(p).dump(2) << "\n";
      return;
    }
    if (!p.started) {
      std::cout << "The design in " << o->folder << " has not saved its first race step yet\n";
      return;
    }
    std::cout << "Design in " << o->folder << ": " << p.phase << ", iteration " << p.iteration << " of "
              << p.nb_iterations << ", " << p.experiments_used << " of " << p.budget << " runs used\n";
    if (p.best)
      std::cout << "  best so far: configuration " << p.best->id << ", mean score " << format_number(p.best->mean_score)
                << " over " << p.best->runs << " runs\n  " << p.best->command_line << "\n";
  });
}

const CommandRegistrar registrar{15, [](CLI::App& app, Context&) {
                                   register_design(app);
                                   register_design_status(app);
                                   register_irace_export(app);
                                 }};

}  // namespace
}  // namespace sd::cli::design_commands
