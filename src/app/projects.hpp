#pragma once
// A user's projects and their design settings (mission, budget), for any front end. Every call
// takes the user explicitly: the CLI passes the one signed in on this machine, a server the one
// of the request's session, so a user only ever reaches their own projects.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/home.hpp"
#include "app/user_files.hpp"
#include "storage/designs.hpp"
#include "storage/projects.hpp"

namespace sd::app {

struct ClusterRequest {
  std::string host, user;
  std::string workdir;  // job folders there ("": ~/swarmdesign)
  std::string binary;   // swarmdesign there ("": the one on its PATH)
};

/// InvalidRequest for a malformed name, host or cluster user; Conflict for a taken name.
storage::Project create_project(Home& home, const storage::User& user, const std::string& name,
                                const std::optional<ClusterRequest>& cluster);
std::vector<storage::Project> list_projects(Home& home, const storage::User& user);
/// The project's designs (the active project when nullopt), oldest first.
std::vector<storage::Design> list_designs(Home& home, const storage::User& user, const std::optional<std::string>& project);
storage::Project select_project(Home& home, const storage::User& user, const std::string& name);
/// Deletes the project, its designs, experiments and files, once `confirmation` repeats its
/// name (InvalidRequest otherwise); Conflict while one of its designs or experiments runs.
void delete_project(Home& home, const storage::User& user, const std::string& name, const std::string& confirmation);
/// Deletes one design of the project (named, or the active one) and its folder; Conflict while
/// it runs, NotFound for a design the project does not have.
void delete_design(Home& home, const storage::User& user, const std::optional<std::string>& project,
                   std::int64_t design_id);
/// NotFound with a hint when none is selected.
storage::Project active_project(Home& home, const storage::User& user);
/// The named project (a server's request, --project), or the active one.
storage::Project project_or_active(Home& home, const storage::User& user, const std::optional<std::string>& name);

/// The budget as typed (app::parse_budget's rule).
storage::Project set_budget(Home& home, const storage::User& user, const std::string& budget);
/// Sets project `project`'s mission and makes it the active project (set-mission, the page's Set
/// mission): a catalogue name, or a mission file that `files` lets the user read, stored by
/// absolute path (mission_reference's rule) so the project runs from any folder. Everything is
/// checked before anything is written: NotFound for a project or file that is not the user's,
/// InvalidRequest for a mission that cannot be loaded, Conflict while a design of it runs.
storage::Project set_project_mission(Home& home, const storage::User& user, const std::string& project,
                                     const std::string& mission, const FileScope& files);
/// set_project_mission on the active project (the CLI's set-mission, Python's configure_project).
storage::Project set_mission(Home& home, const storage::User& user, const std::string& mission,
                             const FileScope& files = FileScope::local());

/// Why the project's mission cannot be used, in the words a user reads after the project that
/// held its mission file was deleted ("its mission file was deleted"); nullopt otherwise.
std::optional<std::string> mission_problem(const storage::Project& project);
/// Whether `mission` (a project's, or one of its designs') names a file of the user's own
/// projects that no longer exists: deleted, with the project that held it or on its own.
bool mission_file_deleted(const std::optional<std::string>& mission, const storage::Project& project);
/// The names of the other projects of `projects` whose mission is a file inside `project`'s
/// folder: the projects that deleting it leaves without a mission.
std::vector<std::string> projects_using_missions_of(const storage::Project& project,
                                                    const std::vector<storage::Project>& projects);

/// A project ready to design in one step (a server's "new project"): name, mission and budget
/// are all checked before anything is written, so a refusal leaves no half-made project. It
/// becomes the active project, as new-project and select-project make it. The mission file, if
/// one is named, must be one `files` lets the user read.
storage::Project create_configured_project(Home& home, const storage::User& user, const std::string& name,
                                           const std::string& mission, const std::string& budget,
                                           const FileScope& files);

/// Changes where the active cluster project's jobs go, or which swarmdesign runs them ("" keeps
/// one); InvalidRequest for a local project or a path that cannot go into a job script.
storage::Project set_cluster_paths(Home& home, const storage::User& user, const std::string& workdir,
                                   const std::string& binary);

}  // namespace sd::app
