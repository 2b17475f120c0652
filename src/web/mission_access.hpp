#pragma once
// Which missions a user may run and see: the catalogue's, and the mission files their own
// projects name (never an arbitrary path of the server's disk).
#include <string>
#include <vector>

#include "app/home.hpp"
#include "missions/mission.hpp"
#include "storage/accounts.hpp"

namespace sd::web {

/// The mission files of the user's projects (absolute paths, as stored).
std::vector<std::string> project_mission_files(app::Home& home, const storage::User& user);
/// The mission; NotFound for a file that none of the user's projects names, InvalidRequest for
/// an unknown name or a malformed file.
Mission load_user_mission(app::Home& home, const storage::User& user, const std::string& reference);

}  // namespace sd::web
