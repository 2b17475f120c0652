// Projects of the signed-in user: new-project, show-projects, select-project, active-project.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "app/accounts.hpp"
#include "app/documents.hpp"
#include "app/projects.hpp"
#include "cli/command_registry.hpp"

namespace sd::cli {
namespace {

using app::kClusterNotYet;

struct ProjectOptions {
  std::string name;
  std::string cluster_host;
  std::string cluster_user;
  bool cluster_given = false;
  bool json = false;
};

std::string where(const storage::Project& project) {
  return project.cluster ? "cluster " + project.cluster->user + "@" + project.cluster->host : "local";
}

void new_project(const ProjectOptions& options) {
  std::optional<app::ClusterRequest> cluster;
  if (options.cluster_given) cluster = app::ClusterRequest{options.cluster_host, options.cluster_user};
  app::Home home;
  const auto project = app::create_project(home, app::signed_in_user(home), options.name, cluster);
  std::cout << "Created " << (cluster ? "cluster" : "local") << " project " << project.name << " in "
            << project.folder.string() << ".\n";
  if (cluster) std::cout << "Cluster: " << cluster->user << "@" << cluster->host << ". " << kClusterNotYet << '\n';
  std::cout << "Select it with: swarmdesign select-project " << project.name << '\n';
}

void show_projects(const ProjectOptions& options) {
  app::Home home;
  const auto list = app::list_projects(home, app::signed_in_user(home));
  if (options.json) {
    std::cout << app::projects_document(list).dump(2) << '\n';
    return;
  }
  if (list.empty()) {
    std::cout << "No projects yet. Create one with: swarmdesign new-project NAME\n";
    return;
  }
  std::size_t name_width = 4, where_width = 5;
  for (const auto& project : list) {
    name_width = std::max(name_width, project.name.size());
    where_width = std::max(where_width, where(project).size());
  }
  const auto row = [&](const std::string& mark, const std::string& name, const std::string& runs_on,
                       const std::string& mission, const std::string& budget) {
    std::cout << mark << std::left << std::setw(static_cast<int>(name_width + 2)) << name
              << std::setw(static_cast<int>(where_width + 2)) << runs_on << std::setw(22) << mission << budget << '\n';
  };
  row("  ", "NAME", "RUNS ON", "MISSION", "BUDGET");
  bool any_active = false;
  for (const auto& project : list) {
    any_active = any_active || project.active;
    row(project.active ? "* " : "  ", project.name, where(project), project.mission.value_or("-"),
        project.budget ? std::to_string(*project.budget) : "-");
  }
  if (any_active) std::cout << "(* active project)\n";
}

void print_project(const storage::Project& project) {
  std::cout << "Active project: " << project.name << '\n'
            << "  runs on: " << where(project) << '\n'
            << "  mission: " << project.mission.value_or("(not set; choose one with: swarmdesign set-mission)") << '\n'
            << "  budget:  "
            << (project.budget ? std::to_string(*project.budget) + " simulation runs"
                               : "(not set; set it with: swarmdesign set-budget N)")
            << '\n'
            << "  folder:  " << project.folder.string() << '\n';
  if (project.cluster) std::cout << kClusterNotYet << '\n';
}

void select_project(const ProjectOptions& options) {
  app::Home home;
  print_project(app::select_project(home, app::signed_in_user(home), options.name));
}

void active_project(const ProjectOptions& options) {
  app::Home home;
  const auto project = app::active_project(home, app::signed_in_user(home));
  if (options.json)
    std::cout << app::project_document(project).dump(2) << '\n';
  else
    print_project(project);
}

CommandRegistrar registrar{20, [](CLI::App& app, Context&) {
  auto options = std::make_shared<ProjectOptions>();

  auto* create = app.add_subcommand("new-project", "Create a project of the signed-in user");
  create->alias("newProject");
  create->add_option("NAME", options->name, "project name: a letter or digit, then letters, digits, '.', '_' or '-'")
      ->required();
  auto* host = create->add_option("--cluster", options->cluster_host, "run on this cluster (host name)");
  auto* user = create->add_option("--cluster-user", options->cluster_user, "your login name on the cluster");
  host->needs(user);
  user->needs(host);
  create->footer(std::string("The project's folder is $SWARMDESIGN_HOME/users/USER/projects/NAME. ") + kClusterNotYet +
                 "\n\nExample:\n  swarmdesign new-project aggregation\n"
                 "  swarmdesign new-project big-run --cluster hpc.example.org --cluster-user alice");
  create->callback([options, host] {
    options->cluster_given = host->count() > 0;
    new_project(*options);
  });

  auto* show = app.add_subcommand("show-projects", "List your projects (* marks the active one)");
  show->alias("showProjects");
  show->add_flag("--json", options->json, "print one JSON document");
  show->footer("Example:\n  swarmdesign show-projects");
  show->callback([options] { show_projects(*options); });

  auto* select = app.add_subcommand("select-project", "Make one of your projects the active one");
  select->alias("selectProject");
  select->add_option("NAME", options->name, "project name")->required();
  select->footer("set-mission, set-budget and the design commands act on the active project.\n\n"
                 "Example:\n  swarmdesign select-project aggregation");
  select->callback([options] { select_project(*options); });

  auto* active = app.add_subcommand("active-project", "Show the active project and its settings");
  active->alias("activeProject");
  active->add_flag("--json", options->json, "print one JSON document");
  active->footer("Example:\n  swarmdesign active-project");
  active->callback([options] { active_project(*options); });
}};

}  // namespace
}  // namespace sd::cli
