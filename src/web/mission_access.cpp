#include "web/mission_access.hpp"

#include <algorithm>

#include "app/errors.hpp"
#include "app/inputs.hpp"
#include "app/projects.hpp"
#include "missions/catalogue.hpp"

namespace sd::web {

std::vector<std::string> project_mission_files(app::Home& home, const storage::User& user) {
  std::vector<std::string> files;
  for (const storage::Project& p : app::list_projects(home, user))
    if (p.mission && is_mission_file(*p.mission) && std::find(files.begin(), files.end(), *p.mission) == files.end())
      files.push_back(*p.mission);
  return files;
}

Mission load_user_mission(app::Home& home, const storage::User& user, const std::string& reference) {
  if (is_mission_file(reference)) {
    const auto files = project_mission_files(home, user);
    if (std::find(files.begin(), files.end(), reference) == files.end())
      throw app::NotFound("no mission file " + reference + " in your projects");
  }
  return app::load_requested_mission(reference);
}

}  // namespace sd::web
