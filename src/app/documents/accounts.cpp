#include "app/documents/accounts.hpp"

#include <nlohmann/json.hpp>

#include "app/projects.hpp"
#include "storage/clock.hpp"

namespace sd::app {

using nlohmann::json;

json project_document(const storage::Project& project) {
  const std::optional<std::string> problem = mission_problem(project);
  json out{{"name", project.name},
           {"folder", project.folder.string()},
           {"location", project.cluster ? "cluster" : "local"},
           {"mission", project.mission ? json(*project.mission) : json()},
           {"mission_problem", problem ? json(*problem) : json()},
           {"budget", project.budget ? json(*project.budget) : json()},
           {"active", project.active},
           {"created", storage::format_time(project.created_at)}};
  if (project.cluster)
    out["cluster"] = {{"host", project.cluster->host},
                      {"user", project.cluster->user},
                      {"folder", project.cluster->workdir_or_default()},
                      {"binary", project.cluster->binary_or_default()}};
  return out;
}

json projects_document(const std::vector<storage::Project>& projects) {
  json list = json::array();
  for (const auto& project : projects) {
    json doc = project_document(project);
    // What deleting this project would leave without a mission: the page's delete dialog names them.
    doc["mission_used_by"] = projects_using_missions_of(project, projects);
    list.push_back(std::move(doc));
  }
  return {{"projects", list}};
}

json users_document(const UserList& users) {
  json list = json::array();
  for (const auto& user : users.users)
    list.push_back({{"name", user.name},
                    {"created", storage::format_time(user.created_at)},
                    {"signed_in", users.me && *users.me == user.id}});
  return {{"users", list}};
}

}  // namespace sd::app
