#include "app/documents/accounts.hpp"

#include <nlohmann/json.hpp>

#include "storage/clock.hpp"

namespace sd::app {

using nlohmann::json;

json project_document(const storage::Project& project) {
  json out{{"name", project.name},
           {"folder", project.folder.string()},
           {"location", project.cluster ? "cluster" : "local"},
           {"mission", project.mission ? json(*project.mission) : json()},
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
  for (const auto& project : projects) list.push_back(project_document(project));
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
