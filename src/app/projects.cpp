#include "app/projects.hpp"

#include "app/errors.hpp"
#include "app/inputs.hpp"
#include "app/user_files.hpp"
#include "missions/catalogue.hpp"
#include "storage/designs.hpp"
#include "storage/validation.hpp"

namespace sd::app {

storage::Project create_project(Home& home, const storage::User& user, const std::string& name,
                                const std::optional<ClusterRequest>& cluster) {
  require(storage::project_name_problem(name));
  std::optional<storage::ClusterConnection> connection;
  if (cluster) {
    require(storage::host_problem(cluster->host));
    require(storage::cluster_user_problem(cluster->user));
    require(storage::cluster_path_problem("cluster folder", cluster->workdir));
    require(storage::cluster_path_problem("cluster binary", cluster->binary));
    connection = storage::ClusterConnection{cluster->host, cluster->user, cluster->workdir, cluster->binary};
  }
  return storage::Projects(home.workspace(), user).create(name, connection);
}

std::vector<storage::Project> list_projects(Home& home, const storage::User& user) {
  return storage::Projects(home.workspace(), user).list();
}

std::vector<storage::Design> list_designs(Home& home, const storage::User& user, const std::optional<std::string>& project) {
  return storage::Designs(home.workspace(), project_or_active(home, user, project)).list();
}

storage::Project select_project(Home& home, const storage::User& user, const std::string& name) {
  require(storage::project_name_problem(name));
  return storage::Projects(home.workspace(), user).select(name);
}

void delete_project(Home& home, const storage::User& user, const std::string& name, const std::string& confirmation) {
  require(storage::project_name_problem(name));
  storage::Projects projects(home.workspace(), user);
  const storage::Project project = projects.get(name);  // NotFound first: nothing to confirm
  // Names are case-insensitive; the confirmation is the name as the user sees it or typed it.
  if (confirmation != name && confirmation != project.name)
    throw InvalidRequest("to delete project " + project.name + ", confirm with its name");
  projects.remove(project.name);
}

void delete_design(Home& home, const storage::User& user, const std::optional<std::string>& project,
                   std::int64_t design_id) {
  storage::Designs(home.workspace(), project_or_active(home, user, project)).remove(design_id);
}

storage::Project set_cluster_paths(Home& home, const storage::User& user, const std::string& workdir,
                                   const std::string& binary) {
  return storage::Projects(home.workspace(), user).set_cluster_paths(workdir, binary);
}

storage::Project project_or_active(Home& home, const storage::User& user, const std::optional<std::string>& name) {
  storage::Projects projects(home.workspace(), user);
  return name ? projects.get(*name) : projects.require_active();
}

storage::Project active_project(Home& home, const storage::User& user) {
  return storage::Projects(home.workspace(), user).require_active();
}

storage::Project set_budget(Home& home, const storage::User& user, const std::string& budget) {
  const long long runs = parse_budget(budget);
  return storage::Projects(home.workspace(), user).set_budget(runs);
}

storage::Project create_configured_project(Home& home, const storage::User& user, const std::string& name,
                                           const std::string& mission, const std::string& budget,
                                           const FileScope& files) {
  require(storage::project_name_problem(name));
  if (mission.empty()) throw InvalidRequest("no mission chosen");
  load_requested_mission(mission, files);
  const long long runs = parse_budget(budget);
  storage::Projects projects(home.workspace(), user);
  projects.create(name, std::nullopt);
  projects.select(name);
  projects.set_mission(mission_reference(mission));
  return projects.set_budget(runs);
}

storage::Project set_mission(Home& home, const storage::User& user, const std::string& mission) {
  if (mission.empty()) throw InvalidRequest("no mission chosen");
  storage::Projects projects(home.workspace(), user);
  projects.require_active();
  try {
    load_requested_mission(mission);
  } catch (const InvalidRequest& e) {
    throw InvalidRequest(std::string(e.what()) + "; run set-mission without a name to choose from the list");
  }
  return projects.set_mission(mission_reference(mission));
}

}  // namespace sd::app
