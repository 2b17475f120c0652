// The active project's design settings: set-budget and set-mission. Running and watching a
// design: run_design_commands.cpp (run-design, test-design) and status_commands.cpp.
#include <CLI/CLI.hpp>
#include <unistd.h>

#include <cstdio>
#include <iomanip>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/accounts.hpp"
#include "app/projects.hpp"
#include "cli/command_registry.hpp"
#include "missions/catalogue.hpp"
#include "storage/validation.hpp"

namespace sd::cli::workflow_commands {
namespace {

using MissionEntry = sd::MissionSummary;

// ---- set-budget ---------------------------------------------------------------------------

struct WorkflowOptions {
  std::string budget;
  std::string mission;
};

void set_budget(const WorkflowOptions& options) {
  app::Home home;
  const auto project = app::set_budget(home, app::signed_in_user(home), options.budget);
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
  app::Home home;
  const storage::User user = app::signed_in_user(home);
  app::active_project(home, user);  // before the prompt: do not ask for a choice that cannot be kept
  const std::string mission = options.mission.empty() ? choose_mission(sd::list_missions()) : options.mission;
  const auto project = app::set_mission(home, user, mission);
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
}  // namespace sd::cli::workflow_commands
