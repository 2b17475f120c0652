#pragma once
// Which missions a user may run and see over the web: the catalogue's, and mission files inside
// their own projects (app/user_files.hpp's rule), never any other path of the server's disk.
#include <string>
#include <vector>

#include "app/home.hpp"
#include "missions/mission.hpp"
#include "app/accounts.hpp"

namespace sd::web {

/// The mission files the user's projects name that the rule lets them use (absolute paths, as
/// stored; a project set up from the CLI with a file elsewhere is not listed), and those
/// uploaded into their projects.
std::vector<std::string> project_mission_files(app::Home& home, const storage::User& user);
/// The mission: InvalidRequest for an unknown name or a malformed file, NotFound (the same
/// words whether the file exists or not) for a file outside the user's projects.
Mission load_user_mission(app::Home& home, const storage::User& user, const std::string& reference);

}  // namespace sd::web
