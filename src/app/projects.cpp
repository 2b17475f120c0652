#include "app/projects.hpp"

#include <filesystem>
#include <system_error>

#include "app/errors.hpp"
#include "app/inputs.hpp"
#include "app/user_files.hpp"
#include "core/bounded_file.hpp"
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

namespace {

/// Whether the mission is a file inside `folder`, both read as real paths as far as they exist
/// (a home reached through a link, a project folder already deleted).
bool mission_file_within(const std::optional<std::string>& mission, const std::filesystem::path& folder) {
  if (!mission || !is_mission_file(*mission)) return false;
  std::error_code ec;
  const auto file = std::filesystem::weakly_canonical(*mission, ec);
  if (ec) return false;
  const auto root = std::filesystem::weakly_canonical(folder, ec);
  return !ec && is_within(file, root);
}

/// A running design keeps the mission it started with; changing the project's under it would
/// make the project name one mission while its design, its progress and the best the page
/// tests belong to another. Stop first, then change: the CLI and the page alike.
void require_no_running_design(Home& home, const storage::Project& project) {
  for (const storage::Design& design : storage::Designs(home.workspace(), project).list())
    if (design.state == storage::DesignState::running)
      throw Conflict("design " + std::to_string(design.id) + " of project " + project.name +
                     " is running; stop it before changing the project's mission");
}

}  // namespace

storage::Project set_project_mission(Home& home, const storage::User& user, const std::string& project,
                                     const std::string& mission, const FileScope& files) {
  if (mission.empty()) throw InvalidRequest("no mission chosen");
  storage::Projects projects(home.workspace(), user);
  const storage::Project target = projects.get(project);
  require_no_running_design(home, target);
  load_requested_mission(mission, files);
  // Selected only now, so a refusal leaves even the active project as it was (the page names
  // the project; set-mission acts on the active one, as every later command will).
  projects.select(target.name);
  return projects.set_mission(mission_reference(mission));
}

storage::Project set_mission(Home& home, const storage::User& user, const std::string& mission,
                             const FileScope& files) {
  if (mission.empty()) throw InvalidRequest("no mission chosen");
  const storage::Project active = active_project(home, user);
  try {
    return set_project_mission(home, user, active.name, mission, files);
  } catch (const InvalidRequest& e) {
    throw InvalidRequest(std::string(e.what()) + "; run set-mission without a name to choose from the list");
  }
}

bool mission_file_deleted(const std::optional<std::string>& mission, const storage::Project& project) {
  // Only a file inside the user's own projects is looked for: whether a file elsewhere exists
  // is not for a server's user to learn (FileScope's one refusal for missing and forbidden).
  if (!mission_file_within(mission, project.folder.parent_path())) return false;
  std::error_code ec;
  return !std::filesystem::exists(*mission, ec) && !ec;
}

std::optional<std::string> mission_problem(const storage::Project& project) {
  if (!mission_file_deleted(project.mission, project)) return std::nullopt;
  return "its mission file was deleted";
}

std::vector<std::string> projects_using_missions_of(const storage::Project& project,
                                                    const std::vector<storage::Project>& projects) {
  std::vector<std::string> users;
  for (const storage::Project& other : projects)
    if (other.id != project.id && mission_file_within(other.mission, project.folder)) users.push_back(other.name);
  return users;
}

}  // namespace sd::app
