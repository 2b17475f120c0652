// status: the active project's current or last design, as app::design_status reads it from the
// designs table and from the design's own design.db (while another process may be writing it).
#include <CLI/CLI.hpp>

#include <cstdint>
#include <iostream>
#include <memory>
#include <optional>

#include "app/accounts.hpp"
#include "app/design_backends.hpp"
#include "app/documents/design.hpp"
#include "app/experiment_job.hpp"
#include "app/export_argos.hpp"
#include "app/project_design.hpp"
#include "cli/command_registry.hpp"
#include "cli/export_display.hpp"
#include "control/config_string.hpp"

namespace sd::cli::status_commands {
namespace {

struct StatusOptions {
  bool complete = false, json = false, argos = false;
  std::int64_t design = 0;  // 0: the last
};

void print_progress(const storage::Design& d, const storage::DesignProgress& p) {
  if (!p.started) {
    std::cout << "  (the design has not saved its first race step yet)\n";
    return;
  }
  std::cout << "  iteration:           " << p.iteration << " of " << p.nb_iterations << "\n"
            << "  experiments used:    " << p.experiments_used << " of " << d.budget << " (remaining "
            << d.budget - p.experiments_used << ")\n"
            << "  current race budget: " << p.race_budget << "\n"
            << "  configurations:      " << p.race_configurations << " in this race (" << p.race_alive << " alive), "
            << p.configurations_sampled
            << " sampled so far\n";
  if (p.best)
    std::cout << "  best so far:         configuration " << p.best->id << ", mean score "
              << format_number(p.best->mean_score) << " over " << p.best->runs << " runs\n"
              << "                       " << p.best->command_line << "\n";
  if (!p.finish_reason.empty()) std::cout << "  finished because:    " << p.finish_reason << "\n";
}

void print_race_log(const std::vector<storage::RaceRecord>& log) {
  std::cout << "\nRace log\n";
  for (const auto& r : log) {
    std::cout << "Iteration " << r.iteration << ": race budget " << r.race_budget << ", " << r.members.size()
              << " configurations, " << r.instances.size() << " instances\n  instances (position:seed):";
    for (const auto& [position, seed] : r.instances) std::cout << " " << position << ":" << seed;
    std::cout << "\n";
    for (const auto& m : r.members) {
      std::cout << "  " << (m.elite ? "elite " : "new   ") << m.configuration.id << ": ";
      if (m.eliminated_after) std::cout << "eliminated after " << *m.eliminated_after << " instances";
      else std::cout << "survived";
      std::cout << ", mean score " << format_number(m.configuration.mean_score) << " over " << m.configuration.runs
                << " runs in this race  " << m.configuration.command_line << "\n";
    }
    std::cout << "  elites:";
    if (r.elites.empty()) std::cout << " (race in progress)";
    for (int id : r.elites) std::cout << " " << id;
    std::cout << "\n";
  }
}

void print_experiments(const std::vector<app::ExperimentProgress>& experiments, bool cluster) {
  for (const auto& e : experiments) {
    std::cout << "Experiment " << e.experiment.name << ": " << storage::to_string(e.experiment.state) << ", "
              << e.designs_done << " of " << e.designs << " designs done";
    if (e.current && e.experiment.state != storage::DesignState::finished)
      std::cout << "; " << (e.experiment.state == storage::DesignState::running ? "now" : "next") << ": "
                << app::mission_label(e.current->plan.mission) << " / " << e.current->plan.condition << " #" << e.current->plan.replicate
                << " (" << storage::to_string(e.current->stage) << ")";
    std::cout << "\n";
    if (cluster && e.experiment.state == storage::DesignState::running)
      std::cout << "  Its designs run on the cluster; bring the finished ones home with: swarmdesign collect\n";
    if (e.experiment.state == storage::DesignState::interrupted)
      std::cout << "  It was interrupted; continue it by running the same swarmdesign experiment command again\n";
    if (e.experiment.state == storage::DesignState::finished)
      std::cout << "  Report it with: swarmdesign report " << e.experiment.name << "\n";
  }
}

void status(const StatusOptions& o) {
  app::Home home;
  const storage::User user = app::signed_in_user(home);
  std::optional<std::int64_t> design;
  if (o.design > 0) design = o.design;
  const auto detail = o.complete ? app::StatusDetail::complete : app::StatusDetail::progress;
  const app::DesignStatus status = app::design_status(home, user, detail, std::nullopt, design);
  const auto experiments = app::experiments_progress(home, user, status.project.name);
  if (o.json) {
    nlohmann::json document = app::status_document(status, detail);
    document["experiments"] = app::experiments_document(experiments);
    if (o.argos && status.design && status.progress.best)
      document["best_argos"] = app::argos_export_document(
          app::try_export_control_software(parse_control_software(status.progress.best->command_line)));
    std::cout << document.dump(2) << "\n";
    return;
  }
  print_experiments(experiments, status.project.cluster.has_value());
  if (!status.design) {
    if (experiments.empty())
      std::cout << "Project " << status.project.name << " has no design yet; start one with: swarmdesign run-design\n";
    return;
  }
  const storage::Design& d = *status.design;
  const auto& job = status.cluster_job;
  std::cout << "Design " << d.id << " of " << status.project.name << ": " << storage::to_string(d.state);
  if (d.state == storage::DesignState::running && !job) std::cout << " (process " << d.pid << ")";
  std::cout << "\n  mission " << d.mission << ", budget " << d.budget << ", seed " << d.seed << ", " << d.architectures
            << " / " << d.flavours << "\n  folder " << d.folder.string() << "\n";
  if (job) {
    std::cout << "  Slurm job " << (job->job_id.empty() ? "(not submitted)" : job->job_id);
    if (!job->slurm_state.empty()) std::cout << ": " << job->slurm_state;
    std::cout << " on " << status.project.cluster->user << "@" << status.project.cluster->host << ", folder "
              << job->folder << "\n";
    if (!job->note.empty()) std::cout << "  " << job->note << "\n";
  }
  print_progress(d, status.progress);
  if (o.argos && status.progress.best)
    print_argos_line(parse_control_software(status.progress.best->command_line), "  ", "best so far");
  if (d.state == storage::DesignState::interrupted)
    std::cout << "It was interrupted; continue it with: swarmdesign run-design\n";
  if (d.state == storage::DesignState::finished) std::cout << "Test it with: swarmdesign test-design\n";
  if (o.complete) print_race_log(status.race_log);
}

CommandRegistrar registrar{41, [](CLI::App& app, Context&) {
  auto o = std::make_shared<StatusOptions>();
  auto* cmd = app.add_subcommand("status", "Show the active project's current or last design, and its experiments");
  cmd->add_flag("--complete", o->complete, "Add the whole race log: every iteration's configurations, instances, "
                                           "eliminations and elites");
  cmd->add_flag("--json", o->json, "Print one JSON document");
  cmd->add_option("--design", o->design, "An earlier design of the project, by its number, instead of the last")
      ->check(CLI::PositiveNumber);
  cmd->add_flag("--argos", o->argos, "Also print the best configuration as ARGoS3-AutoMoDe reads it (export --argos)");
  cmd->footer("Works from another terminal while the design runs.\n\n"
              "Example:\n  swarmdesign status\n  swarmdesign status --complete --json\n  swarmdesign status --design 2\n  swarmdesign status --argos");
  cmd->callback([o] { status(*o); });
}};

}  // namespace
}  // namespace sd::cli::status_commands
