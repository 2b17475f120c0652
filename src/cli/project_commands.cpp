// Projects of the signed-in user: new-project, show-projects, select-project, active-project.
#include <nlohmann/json.hpp>
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

namespace sd::cli::project_commands {
namespace {

/// What a user of a cluster project does next.
std::string cluster_lines(const storage::ClusterConnection& c) {
  return "  cluster: " + c.user + "@" + c.host + ", job folders in " + c.workdir_or_default() + ", program " +
         c.binary_or_default() + "\n  Its designs run as Slurm jobs; check the cluster side with: swarmdesign cluster-check\n";
}

struct ProjectOptions {
  std::string name;
  std::string cluster_host;
  std::string cluster_user;
  std::string cluster_dir, cluster_binary;
  bool cluster_given = false;
  bool json = false;
};

std::string where(const storage::Project& project) {
  return project.cluster ? "cluster " + project.cluster->user + "@" + project.cluster->host : "local";
}

/// The project's mission as the user reads it: a mission file deleted with the project that
/// held it says so, rather than failing later as a file that is not theirs.
std::string mission_text(const storage::Project& project, const std::string& unset) {
  if (!project.mission) return unset;
  const auto problem = app::mission_problem(project);
  return problem ? *project.mission + " (" + *problem + "; choose another with: swarmdesign set-mission)" : *project.mission;
}

/// The same in show-projects' table, where one word says it.
std::string table_mission(const storage::Project& project) {
  if (!project.mission) return "-";
  return app::mission_problem(project) ? *project.mission + " (deleted)" : *project.mission;
}

void new_project(const ProjectOptions& options) {
  std::optional<app::ClusterRequest> cluster;
  if (options.cluster_given)
    cluster = app::ClusterRequest{options.cluster_host, options.cluster_user, options.cluster_dir, options.cluster_binary};
  app::Home home;
  const auto project = app::create_project(home, app::signed_in_user(home), options.name, cluster);
  std::cout << "Created " << (cluster ? "cluster" : "local") << " project " << project.name << " in "
            << project.folder.string() << ".\n";
  if (project.cluster) std::cout << cluster_lines(*project.cluster);
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
  // Each column as wide as its header or its widest value: a mission file's path is long.
  std::size_t name_width = 4, where_width = 7, mission_width = 20;
  for (const auto& project : list) {
    name_width = std::max(name_width, project.name.size());
    where_width = std::max(where_width, where(project).size());
    mission_width = std::max(mission_width, table_mission(project).size());
  }
  const auto row = [&](const std::string& mark, const std::string& name, const std::string& runs_on,
                       const std::string& mission, const std::string& budget) {
    std::cout << mark << std::left << std::setw(static_cast<int>(name_width + 2)) << name
              << std::setw(static_cast<int>(where_width + 2)) << runs_on
              << std::setw(static_cast<int>(mission_width + 2)) << mission << budget << '\n';
  };
  row("  ", "NAME", "RUNS ON", "MISSION", "BUDGET");
  bool any_active = false;
  for (const auto& project : list) {
    any_active = any_active || project.active;
    row(project.active ? "* " : "  ", project.name, where(project), table_mission(project),
        project.budget ? std::to_string(*project.budget) : "-");
  }
  if (any_active) std::cout << "(* active project)\n";
}

void print_project(const storage::Project& project) {
  std::cout << "Active project: " << project.name << '\n'
            << "  runs on: " << where(project) << '\n'
            << "  mission: " << mission_text(project, "(not set; choose one with: swarmdesign set-mission)") << '\n'
            << "  budget:  "
            << (project.budget ? std::to_string(*project.budget) + " simulation runs"
                               : "(not set; set it with: swarmdesign set-budget N)")
            << '\n'
            << "  folder:  " << project.folder.string() << '\n';
  if (project.cluster) std::cout << cluster_lines(*project.cluster);
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
  auto* dir = create->add_option("--cluster-dir", options->cluster_dir,
                                 "where job folders go on the cluster (default ~/swarmdesign)");
  auto* binary = create->add_option("--cluster-binary", options->cluster_binary,
                                    "the swarmdesign program on the cluster (default: the one on its PATH)");
  host->needs(user);
  user->needs(host);
  dir->needs(host);
  binary->needs(host);
  create->footer("The project's folder is $SWARMDESIGN_HOME/users/USER/projects/NAME. A cluster project runs its\n"
                 "designs as Slurm jobs: submitted on this machine when it is the cluster's login node (HOST is\n"
                 "localhost or this machine's name), over ssh otherwise ($SWARMDESIGN_SSH replaces ssh).\n\n"
                 "Example:\n  swarmdesign new-project aggregation\n"
                 "  swarmdesign new-project big-run --cluster hpc.example.org --cluster-user alice\n"
                 "  swarmdesign cluster-check");
  create->callback([options, host] {
    options->cluster_given = host->count() > 0;
    new_project(*options);
  });

  auto* set_cluster = app.add_subcommand("set-cluster", "Change where the active cluster project's jobs run from");
  set_cluster->add_option("--cluster-dir", options->cluster_dir, "where job folders go on the cluster");
  set_cluster->add_option("--cluster-binary", options->cluster_binary, "the swarmdesign program on the cluster");
  set_cluster->footer("Example:\n  swarmdesign set-cluster --cluster-binary /opt/swarmdesign/bin/swarmdesign");
  set_cluster->callback([options] {
    if (options->cluster_dir.empty() && options->cluster_binary.empty())
      throw UsageError("give --cluster-dir, --cluster-binary or both");
    app::Home home;
    print_project(app::set_cluster_paths(home, app::signed_in_user(home), options->cluster_dir, options->cluster_binary));
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
}  // namespace sd::cli::project_commands
