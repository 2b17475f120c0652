// Deleting what a user made: delete-project and delete-design. Both ask for confirmation (the
// project's name, or "yes"), or take --yes; a script without a terminal must say --yes.
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include <cstdint>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "app/accounts.hpp"
#include "app/projects.hpp"
#include "storage/designs.hpp"
#include "storage/projects.hpp"
#include "cli/command_registry.hpp"

namespace sd::cli::delete_commands {
namespace {

struct Options {
  std::string project;
  std::int64_t design = 0;
  bool yes = false;
  bool json = false;
};

/// The line the user typed after `question`; UsageError without a terminal to ask on.
std::string ask(const std::string& question) {
  if (!isatty(STDIN_FILENO)) throw UsageError("nothing deleted: confirm with --yes (no terminal to ask on)");
  std::cerr << question << std::flush;
  std::string answer;
  std::getline(std::cin, answer);
  return answer;
}

void delete_project(const Options& o) {
  app::Home home;
  const storage::User user = app::signed_in_user(home);
  const storage::Project project = app::project_or_active(home, user, o.project);  // an unknown one is said before asking
  // The projects whose mission is one of its files: they are left without one, so say which.
  std::string users_of_its_missions;
  for (const std::string& name : app::projects_using_missions_of(project, storage::Projects(home.workspace(), user).list()))
    users_of_its_missions += (users_of_its_missions.empty() ? "" : ", ") + name;
  const std::string left_without = users_of_its_missions.empty() ? ""
      : "Project(s) " + users_of_its_missions + " take their mission from it: each then needs another (set-mission).\n";
  std::string confirmation = o.project;
  if (!o.yes)
    confirmation = ask("This deletes project " + o.project + " with all its designs, experiments and files.\n" +
                       left_without + "Type its name to delete it: ");
  if (confirmation != o.project) {
    std::cerr << "Nothing deleted: '" << confirmation << "' is not the project's name.\n";
    throw CLI::RuntimeError(1);
  }
  app::delete_project(home, user, o.project, confirmation);
  if (o.json)
    std::cout << nlohmann::json{{"deleted", o.project}}.dump(2) << '\n';
  else
    std::cout << "Deleted project " << o.project << ".\n" << left_without;
}

void delete_design(const Options& o) {
  app::Home home;
  const storage::User user = app::signed_in_user(home);
  const std::optional<std::string> project = o.project.empty() ? std::nullopt : std::optional<std::string>(o.project);
  storage::Designs(home.workspace(), app::project_or_active(home, user, project)).get(o.design);  // said before asking
  if (!o.yes && ask("This deletes design " + std::to_string(o.design) + " and its race data. Type yes to delete it: ") != "yes") {
    std::cerr << "Nothing deleted.\n";
    throw CLI::RuntimeError(1);
  }
  app::delete_design(home, user, project, o.design);
  if (o.json)
    std::cout << nlohmann::json{{"deleted", o.design}}.dump(2) << '\n';
  else
    std::cout << "Deleted design " << o.design << ".\n";
}

CommandRegistrar registrar{21, [](CLI::App& app, Context&) {
  auto o = std::make_shared<Options>();

  auto* project = app.add_subcommand("delete-project", "Delete one of your projects, its designs, experiments and files");
  project->add_option("NAME", o->project, "project name")->required();
  project->add_flag("--yes", o->yes, "Do not ask for the project's name again");
  project->add_flag("--json", o->json, "Print one JSON document");
  project->footer("Refused while one of its designs or experiments runs (stop it first). Nothing of other\n"
                  "projects is touched.\n\nExample:\n  swarmdesign delete-project old-trials");
  project->callback([o] { delete_project(*o); });

  auto* design = app.add_subcommand("delete-design", "Delete one design of the active project and its race data");
  design->add_option("ID", o->design, "the design's number (as status and the web page show it)")
      ->required()->check(CLI::PositiveNumber);
  design->add_option("--project", o->project, "Another of your projects than the active one");
  design->add_flag("--yes", o->yes, "Do not ask for confirmation");
  design->add_flag("--json", o->json, "Print one JSON document");
  design->footer("Refused while the design runs (stop it first with: swarmdesign stop-design).\n\n"
                 "Example:\n  swarmdesign delete-design 3");
  design->callback([o] { delete_design(*o); });
}};

}  // namespace
}  // namespace sd::cli::delete_commands
