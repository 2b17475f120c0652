#include "web/mission_access.hpp"

#include <algorithm>

#include "app/projects.hpp"
#include "app/user_files.hpp"
#include "missions/catalogue.hpp"

namespace sd::web {

std::vector<std::string> project_mission_files(app::Home& home, const storage::User& user) {
  const app::FileScope scope = app::FileScope::own_projects(home, user);
  std::vector<std::string> files;
  for (const storage::Project& p : app::list_projects(home, user))
    if (p.mission && is_mission_file(*p.mission) && scope.allows(*p.mission) &&
        std::find(files.begin(), files.end(), *p.mission) == files.end())
      files.push_back(*p.mission);
  return files;
}

Mission load_user_mission(app::Home& home, const storage::User& user, const std::string& reference) {
  return app::load_requested_mission(reference, app::FileScope::own_projects(home, user));
}

}  // namespace sd::web
