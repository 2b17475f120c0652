// Designing in the active project: run-design (foreground or --detach, resuming an interrupted
// design) and test-design. Where a design runs is the application layer's (app/design_backends.hpp:
// this process, its detached child, or a Slurm job for a cluster project); this file parses and prints.
#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>
#include <optional>

#include "app/accounts.hpp"
#include "app/design_backends.hpp"
#include "app/documents.hpp"
#include "app/inputs.hpp"
#include "app/local_processes.hpp"
#include "app/project_design.hpp"
#include "app/projects.hpp"
#include "cli/command_registry.hpp"
#include "cli/design_display.hpp"
#include "cli/design_flags.hpp"
#include "cli/slurm_flags.hpp"
#include "control/config_string.hpp"

namespace sd::cli::run_design_commands {
namespace {

struct RunDesignOptions {
  DesignSpaceFlags flags;
  RobustDesignFlags robust;
  std::string seed, method;
  unsigned threads = 0;
  bool detach = false;
  bool fresh = false;  // --new: give up an interrupted design instead of resuming it
  app::ClusterJobRequest job;  // a cluster project's sbatch settings
};

/// What was started, said before it runs: resumed, given up, or new; a Slurm job's submission.
void print_started(const app::StartedDesign& s, bool space_given) {
  const storage::Design& d = s.design;
  if (s.abandoned)
    std::cout << "Design " << s.abandoned->id << " of " << s.project.name << " is given up (failed); its data stays in "
              << s.abandoned->folder.string() << ".\n";
  if (s.resumed && s.job)
    std::cout << "Design " << d.id << " of " << s.project.name << " was interrupted; submitted again, it resumes from its "
              << "last checkpoint" << (space_given ? " with the settings it started with" : "") << ".\n";
  else if (s.resumed)
    std::cout << "Design " << d.id << " of " << s.project.name << " was interrupted; resuming it"
              << (space_given ? " with the settings it started with (the flags given are ignored)" : "") << ".\n";
  if (!s.resumed) {
    for (const auto& note : s.notes) std::cerr << "swarmdesign: note: " << note << "\n";
    std::cout << "Design " << d.id << " of " << s.project.name << ": mission " << d.mission << ", budget " << d.budget
              << ", seed " << d.seed << ", " << d.architectures << " / " << d.flavours
              << (d.method == "automode" ? "" : ", method " + d.method) << ".\n";
  }
  if (s.job)
    std::cout << "Submitted to Slurm as job " << s.job->job_id << " on " << s.where << "; its folder there: "
              << s.job->folder << "\n  watch it:  swarmdesign status\n  stop it:   swarmdesign stop-design\n";
}

/// Runs the design (the app records how it ended) and prints the report.
void run_and_report(app::ProjectDesign& d, unsigned threads, ProgressLine::Mode mode) {
  DesignDisplay display(mode, d.prepared.mission.objective.direction == Direction::Maximize);
  const app::DesignOutcome outcome = app::run_project_design(d, {.threads = threads, .observer = &display});
  display.finish();
  print_design_report(*outcome.report);
  std::cout << "Test it on fresh seeds with: swarmdesign test-design\n" << std::flush;
}

void run_design(const RunDesignOptions& o, int mpi_ranks) {
  app::DesignLaunch launch;
  launch.design.space = o.flags.request();
  launch.design.space_given = o.flags.any() || !o.seed.empty() || o.robust.any();
  if (!o.robust.samples.empty() && o.robust.pseudo_realities.empty())
    throw UsageError("--pseudo-reality-samples needs --pseudo-reality SPEC");
  launch.design.pseudo_reality = o.robust.pseudo_realities;
  if (!o.robust.samples.empty()) launch.design.pseudo_reality_samples = o.robust.samples;
  if (!o.seed.empty()) launch.design.seed = app::parse_seed(o.seed);
  if (!o.method.empty()) {
    launch.design.method = &app::search_method(o.method);
    launch.design.space_given = true;
  }
  launch.design.fresh = o.fresh;
  launch.slurm = o.job;
  launch.detach = o.detach;
  launch.mpi_ranks = mpi_ranks;
  // The home's database connection is closed before a fork: SQLite connections must not cross one.
  std::optional<app::StartedDesign> started;
  try {
    app::Home home;
    started.emplace(app::start_design(home, app::signed_in_user(home), launch));
  } catch (const app::AlreadyFinished& done) {
    // The same command again after its design ended (a kill that came too late, a second
    // terminal): its result, as it ended, rather than an identical second design.
    const storage::Design& d = done.design;
    std::cout << "Design " << d.id << " already finished with this mission, budget, design space and seed " << d.seed
              << " (the same command again would only repeat it; --new designs it again).\n"
              << "Best control software (mean score " << format_number(d.best_score.value_or(0.0)) << "):\n  "
              << d.best_config.value_or("") << "\nTest it on fresh seeds with: swarmdesign test-design\n"
              << std::flush;
    return;
  }
  print_started(*started, launch.design.space_given);
  if (!started->run_here) return;  // it runs elsewhere (a Slurm job)
  if (!o.detach) return run_and_report(*started->run_here, o.threads, ProgressLine::terminal_if(true));
  app::LocalProcesses::detach(*started);
  if (started->in_child) return run_and_report(*started->run_here, o.threads, ProgressLine::Mode::Log);
  std::cout << "Design " << started->design.id << " runs in the background (process " << started->child << ").\n"
            << "  watch it:  swarmdesign status\n"
            << "  its log:   " << (started->design.folder / "design.log").string() << "\n";
}

CommandRegistrar registrar{40, [](CLI::App& app, Context& context) {
  auto run = std::make_shared<RunDesignOptions>();
  auto* cmd = app.add_subcommand("run-design", "Run a design for the active project (its mission and budget)");
  cmd->alias("runDesign");
  add_design_space_flags(*cmd, run->flags);
  add_robust_design_flags(*cmd, run->robust);
  cmd->add_option("--seed", run->seed, "Seed of the design (default: a random one, printed)");
  cmd->add_option("--method", run->method, "Optimiser over the design space: " + app::search_method_names() + " (default automode)");
  cmd->add_option("--threads", run->threads, "Simulations in parallel (default: all cores)")->check(CLI::NonNegativeNumber);
  cmd->add_flag("--detach", run->detach, "Run in the background, surviving the terminal closing; watch it with status");
  cmd->add_flag("--new", run->fresh,
                "Start a new design even if the last one was interrupted (that one becomes failed; its folder stays) "
                "or finished with the same settings and --seed (which it would repeat exactly)");
  cmd->footer(
      "Runs in the foreground with a progress line, or with --detach in the background (output in the\n"
      "design's design.log). One design runs per project at a time. If the project's last design was\n"
      "interrupted (killed, machine restarted), run-design resumes it with the settings it started with\n"
      "and it ends exactly as if it had never stopped; when it cannot be resumed (its mission was edited,\n"
      "or it was begun by a swarmdesign whose runs score differently), --new gives it up and starts anew.\n"
      "Run again with the same --seed after its design finished, it prints that design's result rather\n"
      "than repeat it (--new repeats it).\n\n"
      "In a cluster project (new-project --cluster) the design is written as an sbatch script and\n"
      "submitted as a Slurm job, with the Slurm options above; status follows it, stop-design cancels\n"
      "it, and run-design submits an interrupted one again (it resumes from its last checkpoint).\n\n"
      "With --pseudo-reality SPEC the race draws each instance as (seed, pseudo-reality sample), so it keeps\n"
      "control software that holds across robot models (Ligot & Birattari 2020, one step further); assess it\n"
      "afterwards on samples it never saw (swarmdesign assess).\n\n"
      "Example:\n  swarmdesign run-design --fsm --chocolate --seed 1\n  swarmdesign run-design --detach\n"
      "  swarmdesign run-design --pseudo-reality sampled-around --seed 1\n"
      "  swarmdesign run-design --ntasks 64 --time 4:00:00 --partition batch   (cluster project)");
  add_slurm_flags(*cmd, run->job);
  cmd->callback([run, &context] { run_design(*run, context.mpi_ranks); });
}};

}  // namespace
}  // namespace sd::cli::run_design_commands
