// The active project's design settings: set-budget and set-mission. Running and watching a
// design: run_design_commands.cpp (run-design, test-design) and status_commands.cpp.
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/command_registry.hpp"
#include "missions/catalogue.hpp"
#include "storage/errors.hpp"
#include "storage/projects.hpp"
#include "storage/validation.hpp"
#include "storage/workspace.hpp"

namespace sd::cli {
namespace {

// ---- The mission catalogue, behind a seam -------------------------------------------------
// The mission catalogue (built-in missions plus $SWARMDESIGN_HOME/missions).
using MissionEntry = sd::MissionSummary;

struct MissionCatalogue {
  std::function<std::vector<MissionEntry>()> list;
  std::function<bool(const std::string& name_or_path)> exists;
};

MissionCatalogue catalogue() { return {&sd::list_missions, &sd::mission_exists}; }
// ---- end of seam ----------------------------------------------------------------------------

// ---- set-budget ---------------------------------------------------------------------------

struct WorkflowOptions {
  std::string budget;
  std::string mission;
};

void set_budget(const WorkflowOptions& options) {
  const auto budget = storage::parse_positive_integer(options.budget);
  if (!budget)
    throw UsageError("budget must be a positive integer (a number of simulation runs, e.g. 200000), not '" +
                     options.budget + "'");
  storage::Workspace workspace;
  storage::Projects projects(workspace, workspace.require_signed_in_user());
  const auto project = projects.set_budget(*budget);
  std::cout << "Budget of " << project.name << ": " << *project.budget << " simulation runs.\n";
}

// ---- set-mission --------------------------------------------------------------------------

void print_numbered(const std::vector<MissionEntry>& missions) {
  std::cout << "Missions:\n";
  for (std::size_t i = 0; i < missions.size(); ++i) {
    const auto& mission = missions[i];
    std::cout << std::setw(4) << i + 1 << ". " << std::left << std::setw(28) << mission.name << std::setw(15)
              << mission.origin << std::right << mission.robots << " robots, " << mission.duration_s << " s, "
              << mission.direction << '\n';
  }
}

/// A number of the list or a mission name, from one line of standard input.
std::string choose_mission(const std::vector<MissionEntry>& missions) {
  print_numbered(missions);
  std::cout << "Mission (number or name): " << std::flush;
  std::string answer;
  if (!std::getline(std::cin, answer)) throw UsageError("no mission chosen (standard input ended)");
  if (!isatty(STDIN_FILENO)) std::cout << '\n';  // a piped answer is not echoed: end the prompt line
  while (!answer.empty() && (answer.back() == ' ' || answer.back() == '\r')) answer.pop_back();
  if (const auto number = storage::parse_positive_integer(answer)) {
    if (*number > static_cast<std::int64_t>(missions.size()))
      throw UsageError("there is no mission number " + answer + "; choose 1 to " + std::to_string(missions.size()));
    return missions[static_cast<std::size_t>(*number - 1)].name;
  }
  return answer;
}

void set_mission(const WorkflowOptions& options) {
  const MissionCatalogue missions = catalogue();
  storage::Workspace workspace;
  storage::Projects projects(workspace, workspace.require_signed_in_user());
  projects.require_active();  // before the prompt: do not ask for a choice that cannot be kept

  std::string mission = options.mission.empty() ? choose_mission(missions.list()) : options.mission;
  if (mission.empty()) throw UsageError("no mission chosen");
  if (!missions.exists(mission))
    throw storage::NotFound("unknown mission '" + mission + "'; run set-mission without a name to choose from the list");
  // A mission file is kept by absolute path so the project works from any directory.
  if (mission.find('/') != std::string::npos) mission = std::filesystem::absolute(mission).lexically_normal().string();
  const auto project = projects.set_mission(mission);
  std::cout << "Mission of " << project.name << ": " << *project.mission << ".\n";
}

CommandRegistrar registrar{30, [](CLI::App& app, Context&) {
  auto options = std::make_shared<WorkflowOptions>();

  auto* budget = app.add_subcommand("set-budget", "Set the design budget of the active project");
  budget->alias("setBudget");
  budget->add_option("N", options->budget, "number of simulation runs the design may use (a positive integer)")
      ->required();
  budget->footer("Example:\n  swarmdesign set-budget 200000");
  budget->callback([options] { set_budget(*options); });

  auto* mission = app.add_subcommand("set-mission", "Choose the mission of the active project");
  mission->alias("setMission");
  mission->add_option("NAME", options->mission, "mission name or mission file; without it: a numbered list and a prompt");
  mission->footer("Without NAME, prints the missions numbered and reads a number or a name from standard input.\n\n"
                  "Example:\n  swarmdesign set-mission aac\n  swarmdesign set-mission");
  mission->callback([options] { set_mission(*options); });
}};

}  // namespace
}  // namespace sd::cli
