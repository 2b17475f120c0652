// status: the active project's current or last design, read from the designs table and from
// the design's own design.db (while another process may be writing it).
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>

#include "cli/command_registry.hpp"
#include "control/config_string.hpp"
#include "storage/clock.hpp"
#include "storage/design_status.hpp"
#include "storage/design_store.hpp"
#include "storage/designs.hpp"
#include "storage/projects.hpp"
#include "storage/workspace.hpp"

namespace sd::cli {
namespace {

using nlohmann::json;

struct StatusOptions {
  bool complete = false, json = false;
};

json to_json(const storage::ConfigurationScore& c) {
  return {{"id", c.id}, {"configuration", c.command_line}, {"mean_score", c.mean_score}, {"runs", c.runs}};
}

json to_json(const storage::DesignProgress& p) {
  json out{{"started", p.started},
           {"phase", p.phase},
           {"iteration", p.iteration},
           {"total_iterations", p.nb_iterations},
           {"experiments_used", p.experiments_used},
           {"remaining_budget", p.budget - p.experiments_used},
           {"race_budget", p.race_budget},
           {"race_configurations", p.race_configurations},
           {"configurations_sampled", p.configurations_sampled},
           {"best", p.best ? to_json(*p.best) : json()}};
  if (!p.finish_reason.empty()) out["finish_reason"] = p.finish_reason;
  return out;
}

json to_json(const std::vector<storage::RaceRecord>& log) {
  json races = json::array();
  for (const auto& r : log) {
    json instances = json::array(), members = json::array();
    for (const auto& [position, seed] : r.instances) instances.push_back({{"position", position}, {"seed", seed}});
    for (const auto& m : r.members) {
      json member = to_json(m.configuration);
      member["elite"] = m.elite;
      member["eliminated_after"] = m.eliminated_after ? json(*m.eliminated_after) : json();
      members.push_back(std::move(member));
    }
    races.push_back({{"iteration", r.iteration}, {"race_budget", r.race_budget}, {"instances", instances},
                     {"configurations", members}, {"elites", r.elites}});
  }
  return races;
}

void print_progress(const storage::Design& d, const storage::DesignProgress& p) {
  if (!p.started) {
    std::cout << "  (the design has not saved its first race step yet)\n";
    return;
  }
  std::cout << "  iteration:           " << p.iteration << " of " << p.nb_iterations << "\n"
            << "  experiments used:    " << p.experiments_used << " of " << d.budget << " (remaining "
            << d.budget - p.experiments_used << ")\n"
            << "  current race budget: " << p.race_budget << "\n"
            << "  configurations:      " << p.race_configurations << " in this race, " << p.configurations_sampled
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

void status(const StatusOptions& o) {
  storage::Workspace workspace;
  storage::Projects projects(workspace, workspace.require_signed_in_user());
  const storage::Project project = projects.require_active();
  const auto latest = storage::Designs(workspace, project).latest();
  if (!latest) {
    if (o.json) std::cout << json{{"project", project.name}, {"design", nullptr}}.dump(2) << "\n";
    else std::cout << "Project " << project.name << " has no design yet; start one with: swarmdesign run-design\n";
    return;
  }
  const storage::Design& d = *latest;
  storage::DesignProgress progress;
  std::vector<storage::RaceRecord> log;
  try {
    if (std::filesystem::exists(storage::DesignStore::file_in(d.folder))) {
      progress = storage::read_design_progress(d.folder);
      if (o.complete) log = storage::read_race_log(d.folder);
    }
  } catch (const storage::DesignFolderError&) {
    // A design that has just started may not have committed its tables yet.
    if (d.state != storage::DesignState::running) throw;
  }

  if (o.json) {
    json out{{"project", project.name},
             {"design",
              {{"id", d.id}, {"state", storage::to_string(d.state)}, {"pid", d.pid}, {"folder", d.folder.string()},
               {"mission", d.mission}, {"budget", d.budget}, {"seed", d.seed}, {"architectures", d.architectures},
               {"flavours", d.flavours}, {"created", storage::format_time(d.created_at)}}},
             {"progress", to_json(progress)}};
    if (o.complete) out["race_log"] = to_json(log);
    std::cout << out.dump(2) << "\n";
    return;
  }
  std::cout << "Design " << d.id << " of " << project.name << ": " << storage::to_string(d.state);
  if (d.state == storage::DesignState::running) std::cout << " (process " << d.pid << ")";
  std::cout << "\n  mission " << d.mission << ", budget " << d.budget << ", seed " << d.seed << ", " << d.architectures
            << " / " << d.flavours << "\n  folder " << d.folder.string() << "\n";
  print_progress(d, progress);
  if (d.state == storage::DesignState::interrupted)
    std::cout << "It was interrupted; continue it with: swarmdesign run-design\n";
  if (d.state == storage::DesignState::finished) std::cout << "Test it with: swarmdesign test-design\n";
  if (o.complete) print_race_log(log);
}

CommandRegistrar registrar{41, [](CLI::App& app, Context&) {
  auto o = std::make_shared<StatusOptions>();
  auto* cmd = app.add_subcommand("status", "Show the active project's current or last design");
  cmd->add_flag("--complete", o->complete, "Add the whole race log: every iteration's configurations, instances, "
                                           "eliminations and elites");
  cmd->add_flag("--json", o->json, "Print one JSON document");
  cmd->footer("Works from another terminal while the design runs.\n\n"
              "Example:\n  swarmdesign status\n  swarmdesign status --complete --json");
  cmd->callback([o] { status(*o); });
}};

}  // namespace
}  // namespace sd::cli
