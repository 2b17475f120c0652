// Designing in the active project: run-design (foreground or --detach, resuming an interrupted
// design) and test-design. The jobs are the application layer's (app/project_design.hpp); this
// file parses, prints, and forks a detached design.
#include <CLI/CLI.hpp>
#include <fcntl.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>

#include "app/accounts.hpp"
#include "app/cluster_designs.hpp"
#include "app/documents.hpp"
#include "app/evaluation_job.hpp"
#include "app/inputs.hpp"
#include "app/project_design.hpp"
#include "app/projects.hpp"
#include "cli/command_registry.hpp"
#include "cli/control_software_input.hpp"
#include "cli/design_display.hpp"
#include "cli/design_flags.hpp"
#include "cli/export_display.hpp"
#include "cli/score_output.hpp"
#include "cli/slurm_flags.hpp"
#include "storage/lease.hpp"

namespace sd::cli {
namespace {

struct RunDesignOptions {
  DesignSpaceFlags flags;
  std::string seed;
  unsigned threads = 0;
  bool detach = false;
  bool fresh = false;  // --new: give up an interrupted design instead of resuming it
  app::ClusterJobRequest job;  // a cluster project's sbatch settings
};

/// This process's lease owner for a design it runs.
std::string this_process() { return storage::owner_text(storage::local_process()); }

app::ProjectDesign start(app::Home& home, const RunDesignOptions& o) {
  app::ProjectDesignRequest request;
  request.space = o.flags.request();
  request.space_given = o.flags.any() || !o.seed.empty();
  if (!o.seed.empty()) request.seed = app::parse_seed(o.seed);
  request.fresh = o.fresh;
  request.owner = this_process();
  app::ProjectDesign d = app::start_project_design(home, app::signed_in_user(home), request);
  if (d.resumed) {
    std::cout << "Design " << d.design.id << " of " << d.project.name << " was interrupted; resuming it"
              << (request.space_given ? " with the settings it started with (the flags given are ignored)" : "")
              << ".\n";
    return d;
  }
  if (d.abandoned)
    std::cout << "Design " << d.abandoned->id << " of " << d.project.name << " is given up (failed); its data stays in "
              << d.abandoned->folder.string() << ".\n";
  for (const auto& note : d.prepared.choice.notes) std::cerr << "swarmdesign: note: " << note << "\n";
  std::cout << "Design " << d.design.id << " of " << d.project.name << ": mission " << d.design.mission << ", budget "
            << d.design.budget << ", seed " << d.design.seed << ", " << d.design.architectures << " / "
            << d.design.flavours << ".\n";
  return d;
}

/// Runs the design (the app records how it ended) and prints the report.
void run_and_report(app::ProjectDesign& d, unsigned threads, ProgressLine::Mode mode) {
  DesignDisplay display(mode, d.prepared.mission.objective.direction == Direction::Maximize);
  const app::DesignOutcome outcome = app::run_project_design(d, {.threads = threads, .observer = &display});
  display.finish();
  print_design_report(*outcome.report);
  std::cout << "Test it on fresh seeds with: swarmdesign test-design\n" << std::flush;
}

/// Continues in a child process that survives the terminal: its own session, no terminal,
/// output in DIR/design.log. Parent and child both hand the design's lease to the child. No
/// database connection may be open here (SQLite's rule for fork).
void detach(app::ProjectDesign& d, unsigned threads) {
  const auto log = d.design.folder / "design.log";
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
    d.design.owner = this_process();  // the parent records the same owner for us
    run_and_report(d, threads, ProgressLine::Mode::Log);
    return;
  }
  app::hand_over(d, storage::owner_text(storage::local_process(child)));
  std::cout << "Design " << d.design.id << " runs in the background (process " << child << ").\n"
            << "  watch it:  swarmdesign status\n"
            << "  its log:   " << log.string() << "\n";
}

/// A cluster project's design goes to Slurm: submitted, or submitted again to resume.
void submit(app::Home& home, const RunDesignOptions& o) {
  app::ProjectDesignRequest request;
  request.space = o.flags.request();
  request.space_given = o.flags.any() || !o.seed.empty();
  if (!o.seed.empty()) request.seed = app::parse_seed(o.seed);
  request.fresh = o.fresh;
  const app::ClusterSubmission s = app::submit_cluster_design(home, app::signed_in_user(home), request, o.job);
  const storage::Design& d = s.design;
  if (s.resubmitted)
    std::cout << "Design " << d.id << " of " << s.project.name << " was interrupted; submitted again, it resumes from its "
              << "last checkpoint" << (request.space_given ? " with the settings it started with" : "") << ".\n";
  else
    std::cout << "Design " << d.id << " of " << s.project.name << ": mission " << d.mission << ", budget " << d.budget
              << ", seed " << d.seed << ", " << d.architectures << " / " << d.flavours << ".\n";
  std::cout << "Submitted to Slurm as job " << s.job.job_id << " on " << s.where << "; its folder there: " << s.job.folder
            << "\n  watch it:  swarmdesign status\n  stop it:   swarmdesign stop-design\n";
}

void run_design(const RunDesignOptions& o, int mpi_ranks) {
  // The home's database connection is closed before a fork: SQLite connections must not cross one.
  std::optional<app::ProjectDesign> started;
  {
    app::Home home;
    if (app::active_project(home, app::signed_in_user(home)).cluster) {
      if (o.detach) throw UsageError("--detach is for a local project: a cluster project's design runs as a Slurm job anyway");
      return submit(home, o);
    }
    if (o.job.given())
      throw UsageError("--nodes, --ntasks, --cpus-per-task, --time, --partition and --account are for a cluster project; "
                       "this one runs on this machine");
    // A forked child would leave the MPI job behind: mpirun waits for rank 0 anyway.
    if (o.detach && mpi_ranks > 1)
      throw UsageError("--detach cannot be used under mpirun (mpirun waits for its ranks); leave it out");
    started.emplace(start(home, o));
  }
  app::ProjectDesign& d = *started;
  if (o.detach) return detach(d, o.threads);
  run_and_report(d, o.threads, ProgressLine::terminal_if(true));
}

struct TestDesignOptions {
  std::string seeds = "1-10";
  int threads = 0;
  bool json = false, argos = false;
  ControlSoftwareOptions software;
};

void test_design(const TestDesignOptions& o, const Context& context) {
  const std::vector<std::uint64_t> seeds = app::parse_seed_range(o.seeds);
  if (o.argos && o.json)
    throw UsageError("--argos prints a text line; leave out --json (or use: swarmdesign export --argos --json)");
  std::optional<ControlSoftware> given;
  if (context.has_control_software() || !o.software.config_file.empty()) given = read_control_software(context, o.software);
  app::Home home;
  const app::TestTarget target = app::test_target(home, app::signed_in_user(home), given);
  if (target.design_id && !o.json)
    std::cout << "Testing the best control software of design " << *target.design_id << ":\n  " << target.configuration
              << "\n";
  if (o.argos) print_argos_line(target.software, "  ", "");
  score_and_print(target.mission, target.software, seeds, o.threads, o.json);
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
      "In a cluster project (new-project --cluster) the design is written as an sbatch script and\n"
      "submitted as a Slurm job, with the Slurm options above; status follows it, stop-design cancels\n"
      "it, and run-design submits an interrupted one again (it resumes from its last checkpoint).\n\n"
      "Example:\n  swarmdesign run-design --fsm --chocolate --seed 1\n  swarmdesign run-design --detach\n"
      "  swarmdesign run-design --ntasks 64 --time 4:00:00 --partition batch   (cluster project)");
  add_slurm_flags(*cmd, run->job);
  cmd->callback([run, &context] { run_design(*run, context.mpi_ranks); });

  auto test = std::make_shared<TestDesignOptions>();
  auto* tcmd = app.add_subcommand("test-design", "Evaluate control software on the active project's mission");
  tcmd->alias("testDesign");
  tcmd->add_option("--seeds", test->seeds, "Seeds A-B to evaluate on (default 1-10)");
  tcmd->add_option("--threads", test->threads, "Worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
  tcmd->add_flag("--json", test->json, "Print one JSON document");
  tcmd->add_flag("--argos", test->argos, "Also print the control software as ARGoS3-AutoMoDe reads it (export --argos)");
  add_control_software_options(*tcmd, test->software);
  tcmd->footer(
      "Without control software, tests the best control software of the project's last finished design.\n"
      "The control software ends the command line.\n\n"
      "Example:\n  swarmdesign test-design --seeds 1-20\n"
      "  swarmdesign test-design --seeds 1-20 --fsm-config --nstates 1 --s0 10 --rwm0 50\n"
      "  swarmdesign test-design --argos");
  tcmd->callback([test, &context] { test_design(*test, context); });
}};

}  // namespace
}  // namespace sd::cli
