#pragma once
// The documents of accounts and projects: a project, a user's projects, the users.
#include <nlohmann/json_fwd.hpp>

#include <vector>

#include "app/accounts.hpp"
#include "storage/projects.hpp"

namespace sd::app {

nlohmann::json project_document(const storage::Project& project);
nlohmann::json projects_document(const std::vector<storage::Project>& projects);
nlohmann::json users_document(const UserList& users);

}  // namespace sd::app
