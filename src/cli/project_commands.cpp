// Projects of the signed-in user: new-project, show-projects, select-project, active-project.
#include <CLI/CLI.hpp>

#include <algorithm>
#include <iomanip>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "cli/command_registry.hpp"
#include "storage/clock.hpp"
#include "storage/projects.hpp"
#include "storage/validation.hpp"
#include "storage/workspace.hpp"

namespace sd::cli {
namespace {

const char* const kClusterNotYet =
    "Running designs on a cluster is not available yet in this version of SwarmDesign: the "
    "connection is recorded, but designs of this project cannot be run until it is.";

struct ProjectOptions {
  std::string name;
  std::string cluster_host;
  std::string cluster_user;
  bool cluster_given = false;
  bool json = false;
};

void require(const std::string& problem) {
  if (!problem.empty()) throw UsageError(problem);
}

std::string where(const storage::Project& project) {
  return project.cluster ? "cluster " + project.cluster->user + "@" + project.cluster->host : "local";
}

nlohmann::json to_json(const storage::Project& project) {
  nlohmann::json json{{"name", project.name},
                      {"folder", project.folder.string()},
                      {"location", project.cluster ? "cluster" : "local"},
                      {"mission", project.mission ? nlohmann::json(*project.mission) : nlohmann::json()},
                      {"budget", project.budget ? nlohmann::json(*project.budget) : nlohmann::json()},
                      {"active", project.active},
                      {"created", storage::format_time(project.created_at)}};
  if (project.cluster) json["cluster"] = {{"host", project.cluster->host}, {"user", project.cluster->user}};
  return json;
}

void new_project(const ProjectOptions& options) {
  require(storage::project_name_problem(options.name));
  std::optional<storage::ClusterConnection> cluster;
  if (options.cluster_given) {
    require(storage::host_problem(options.cluster_host));
    require(storage::cluster_user_problem(options.cluster_user));
    cluster = storage::ClusterConnection{options.cluster_host, options.cluster_user};
  }
  storage::Workspace workspace;
  storage::Projects projects(workspace, workspace.require_signed_in_user());
  const auto project = projects.create(options.name, cluster);
  std::cout << "Created " << (cluster ? "cluster" : "local") << " project " << project.name << " in "
            << project.folder.string() << ".\n";
  if (cluster) std::cout << "Cluster: " << cluster->user << "@" << cluster->host << ". " << kClusterNotYet << '\n';
  std::cout << "Select it with: swarmdesign select-project " << project.name << '\n';
}

void show_projects(const ProjectOptions& options) {
  storage::Workspace workspace;
  storage::Projects projects(workspace, workspace.require_signed_in_user());
  const auto list = projects.list();
  if (options.json) {
    auto array = nlohmann::json::array();
    for (const auto& project : list) array.push_back(to_json(project));
    std::cout << nlohmann::json{{"projects", array}}.dump(2) << '\n';
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
  require(storage::project_name_problem(options.name));
  storage::Workspace workspace;
  storage::Projects projects(workspace, workspace.require_signed_in_user());
  print_project(projects.select(options.name));
}

void active_project(const ProjectOptions& options) {
  storage::Workspace workspace;
  storage::Projects projects(workspace, workspace.require_signed_in_user());
  const auto project = projects.require_active();
  if (options.json)
    std::cout << to_json(project).dump(2) << '\n';
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
