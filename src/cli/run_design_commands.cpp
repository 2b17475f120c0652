// Designing in the active project: run-design (foreground or --detach, resuming an interrupted
// design) and test-design. The design itself runs exactly as `swarmdesign design` does, in the
// folder the designs table gives it.
#include <CLI/CLI.hpp>
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <memory>

#include "cli/command_registry.hpp"
#include "cli/control_software_input.hpp"
#include "cli/design_flags.hpp"
#include "cli/design_run.hpp"
#include "cli/score_report.hpp"
#include "control/config_string.hpp"
#include "missions/catalogue.hpp"
#include "storage/design_store.hpp"
#include "storage/designs.hpp"
#include "storage/errors.hpp"
#include "storage/projects.hpp"
#include "storage/workspace.hpp"

namespace sd::cli {
namespace {

struct RunDesignOptions {
  DesignSpaceFlags flags;
  std::string seed;
  unsigned threads = 0;
  bool detach = false;
  bool fresh = false;  // --new: give up an interrupted design instead of resuming it
};

/// A design the command has recorded and is about to run.
struct Started {
  storage::Project project;
  storage::Design design;
  PreparedDesign prepared;
};

/// Resumes the project's interrupted design, or records a new one. Everything that can be
/// refused is checked before the designs table changes.
Started start_or_resume(const RunDesignOptions& o) {
  storage::Workspace workspace;
  storage::Projects projects(workspace, workspace.require_signed_in_user());
  storage::Project project = projects.require_active();
  storage::Designs designs(workspace, project);
  const auto latest = designs.latest();

  if (latest && latest->state == storage::DesignState::interrupted && !project.cluster && !o.fresh) {
    PreparedDesign prepared;
    try {
      prepared = std::filesystem::exists(storage::DesignStore::file_in(latest->folder))
                     ? prepare_resume(latest->folder, true)
                     : prepare_new_design({latest->mission, latest->budget,
                                           design::request_from_text(latest->architectures, latest->flavours),
                                           latest->seed},
                                          latest->folder);  // killed before its first checkpoint
    } catch (const storage::DesignFolderError& e) {
      throw storage::DesignFolderError("design " + std::to_string(latest->id) + " of " + project.name +
                              " was interrupted and cannot be resumed: " + e.what() +
                              " (run-design --new gives it up and starts a new design)");
    }
    std::cout << "Design " << latest->id << " of " << project.name << " was interrupted; resuming it";
    std::cout << (o.flags.any() || !o.seed.empty() ? " with the settings it started with (the flags given are ignored)"
                                                   : "")
              << ".\n";
    storage::Design resumed = designs.resume(latest->id, ::getpid());
    return {project, resumed, std::move(prepared)};
  }

  const std::uint64_t seed = o.seed.empty() ? random_seed() : parse_seed(o.seed);
  design::DesignSpaceChoice choice;
  try {
    choice = design::resolve_design_space(o.flags.request());
  } catch (const std::invalid_argument& e) {
    throw UsageError(e.what());
  }
  std::optional<PreparedDesign> checked;
  if (project.mission && project.budget && !project.cluster)  // else Designs::start says what is missing
    checked = check_new_design({*project.mission, *project.budget, o.flags.request(), seed});
  if (checked && latest && latest->state == storage::DesignState::interrupted && o.fresh) {
    designs.abandon(latest->id);
    std::cout << "Design " << latest->id << " of " << project.name << " is given up (failed); its data stays in "
              << latest->folder.string() << ".\n";
  }
  storage::Design design =
      designs.start({choice.architectures_text(), choice.flavours_text(), seed, static_cast<int>(::getpid())});
  if (!checked) throw std::logic_error("a design started without a mission or budget");
  PreparedDesign prepared = std::move(*checked);
  prepared.folder = design.folder;
  for (const auto& note : prepared.choice.notes) std::cerr << "swarmdesign: note: " << note << "\n";
  std::cout << "Design " << design.id << " of " << project.name << ": mission " << design.mission << ", budget "
            << design.budget << ", seed " << seed << ", " << choice.architectures_text() << " / "
            << choice.flavours_text() << ".\n";
  return {project, design, std::move(prepared)};
}

/// Runs the design and records how it ended in the designs table.
void run_and_record(Started& s, const RunOptions& options) {
  DesignReport report;
  try {
    report = run_prepared_design(s.prepared, options);
  } catch (...) {
    storage::Workspace workspace;
    storage::Designs(workspace, s.project).mark_failed(s.design.id);
    throw;
  }
  storage::Workspace workspace;
  storage::Designs(workspace, s.project).finish(s.design.id, report.elites.front().configuration,
                                                report.elites.front().mean_score);
  print_design_report(report, false);
  std::cout << "Test it on fresh seeds with: swarmdesign test-design\n" << std::flush;
}

/// Continues in a child process that survives the terminal: its own session, no terminal,
/// output in DIR/design.log. The parent records the child as the design's process.
void detach(Started& s, const RunOptions& options) {
  const auto log = s.design.folder / "design.log";
  std::cout << std::flush;
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child < 0) throw std::runtime_error("cannot start the background process");
  if (child == 0) {
    ::setsid();
    std::signal(SIGHUP, SIG_IGN);
    const int null_fd = ::open("/dev/null", O_RDONLY);
    const int log_fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0600);
    if (null_fd < 0 || log_fd < 0) std::_Exit(1);
    ::dup2(null_fd, STDIN_FILENO);
    ::dup2(log_fd, STDOUT_FILENO);
    ::dup2(log_fd, STDERR_FILENO);
    ::close(null_fd);
    ::close(log_fd);
    run_and_record(s, {options.threads, false, true});
    return;
  }
  storage::Workspace workspace;
  storage::Designs(workspace, s.project).set_pid(s.design.id, static_cast<int>(child));
  std::cout << "Design " << s.design.id << " runs in the background (process " << child << ").\n"
            << "  watch it:  swarmdesign status\n"
            << "  its log:   " << log.string() << "\n";
}

void run_design(const RunDesignOptions& o) {
  Started started = start_or_resume(o);
  if (o.detach) return detach(started, {o.threads, false, true});
  run_and_record(started, {o.threads, isatty(STDERR_FILENO) != 0, false});
}

struct TestDesignOptions {
  std::string seeds = "1-10";
  int threads = 0;
  bool json = false;
  ControlSoftwareOptions software;
};

void test_design(const TestDesignOptions& o, const Context& context) {
  storage::Workspace workspace;
  storage::Projects projects(workspace, workspace.require_signed_in_user());
  const storage::Project project = projects.require_active();
  if (!project.mission)
    throw storage::NotFound("project " + project.name + " has no mission; choose one with: swarmdesign set-mission");
  const std::vector<std::uint64_t> seeds = parse_seed_range(o.seeds);
  ControlSoftware software;
  try {
    if (context.has_control_software() || !o.software.config_file.empty()) {
      software = read_control_software(context, o.software);
    } else {
      const auto designs = storage::Designs(workspace, project).list();
      const auto finished = std::find_if(designs.rbegin(), designs.rend(), [](const auto& d) { return d.best_config; });
      if (finished == designs.rend())
        throw UsageError("project " + project.name +
                         " has no finished design yet: give the control software (--fsm-config ...) to test");
      if (!o.json)
        std::cout << "Testing the best control software of design " << finished->id << ":\n  " << *finished->best_config
                  << "\n";
      software = parse_control_software(*finished->best_config);
    }
  } catch (const ConfigError& e) {
    throw UsageError(e.what());
  }
  Mission mission;
  try {
    mission = load_mission(*project.mission);
  } catch (const MissionError& e) {
    throw storage::NotFound("the mission of project " + project.name + " cannot be loaded: " + e.what());
  }
  const auto scores = score_seeds(mission, software, seeds, o.threads, isatty(STDERR_FILENO) && !o.json);
  print_scores(mission, software, seeds, scores, o.json);
}

CommandRegistrar registrar{40, [](CLI::App& app, Context& context) {
  auto run = std::make_shared<RunDesignOptions>();
  auto* cmd = app.add_subcommand("run-design", "Run a design for the active project (its mission and budget)");
  cmd->alias("runDesign");
  add_design_space_flags(*cmd, run->flags);
  cmd->add_option("--seed", run->seed, "Seed of the design (default: a random one, printed)");
  cmd->add_option("--threads", run->threads, "Simulations in parallel (default: all cores)")->check(CLI::NonNegativeNumber);
  cmd->add_flag("--detach", run->detach, "Run in the background, surviving the terminal closing; watch it with status");
  cmd->add_flag("--new", run->fresh,
                "Start a new design even if the last one was interrupted; that one becomes failed (its folder stays)");
  cmd->footer(
      "Runs in the foreground with a progress line, or with --detach in the background (output in the\n"
      "design's design.log). One design runs per project at a time. If the project's last design was\n"
      "interrupted (killed, machine restarted), run-design resumes it with the settings it started with\n"
      "and it ends exactly as if it had never stopped; when it cannot be resumed (its mission was edited,\n"
      "or it was begun by a swarmdesign whose runs score differently), --new gives it up and starts anew.\n\n"
      "Example:\n  swarmdesign run-design --fsm --chocolate --seed 1\n  swarmdesign run-design --detach");
  cmd->callback([run] { run_design(*run); });

  auto test = std::make_shared<TestDesignOptions>();
  auto* tcmd = app.add_subcommand("test-design", "Evaluate control software on the active project's mission");
  tcmd->alias("testDesign");
  tcmd->add_option("--seeds", test->seeds, "Seeds A-B to evaluate on (default 1-10)");
  tcmd->add_option("--threads", test->threads, "Worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
  tcmd->add_flag("--json", test->json, "Print one JSON document");
  add_control_software_options(*tcmd, test->software);
  tcmd->footer(
      "Without control software, tests the best control software of the project's last finished design.\n"
      "The control software ends the command line.\n\n"
      "Example:\n  swarmdesign test-design --seeds 1-20\n"
      "  swarmdesign test-design --seeds 1-20 --fsm-config --nstates 1 --s0 10 --rwm0 50");
  tcmd->callback([test, &context] { test_design(*test, context); });
}};

}  // namespace
}  // namespace sd::cli
