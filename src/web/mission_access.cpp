#include "web/mission_access.hpp"

#include <algorithm>

#include "app/project_missions.hpp"
#include "app/projects.hpp"
#include "app/user_files.hpp"
#include "missions/catalogue.hpp"

namespace sd::web {

std::vector<std::string> project_mission_files(app::Home& home, const storage::User& user) {
  const app::FileScope scope = app::FileScope::own_projects(home, user);
  std::vector<std::string> files;
  const auto add = [&](const std::string& file) {
    if (std::find(files.begin(), files.end(), file) == files.end()) files.push_back(file);
  };
  for (const storage::Project& p : app::list_projects(home, user)) {
    if (p.mission && is_mission_file(*p.mission) && scope.allows(*p.mission)) add(*p.mission);
    for (const app::ProjectMission& m : app::list_project_missions(home, user, p.name)) add(m.file.string());
  }
  return files;
}

Mission load_user_mission(app::Home& home, const storage::User& user, const std::string& reference) {
  return app::load_requested_mission(reference, app::FileScope::own_projects(home, user));
}

}  // namespace sd::web
