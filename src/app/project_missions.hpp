#pragma once
// Mission files a user brings into a project (the web page's upload and mission editor): one
// JSON document per file, <project>/missions/<name>.json, the same format `swarmdesign
// set-mission FILE` reads. Stored only once it reads as a mission whose robots can be placed.
#include <filesystem>
#include <string>
#include <vector>

#include "app/home.hpp"
#include "missions/mission.hpp"
#include "storage/accounts.hpp"

namespace sd::app {

struct ProjectMission {
  std::string name;             // the file's stem
  std::filesystem::path file;   // absolute: what a project, a run or a design names
};

/// The project's mission files, by name; NotFound for another user's project.
std::vector<ProjectMission> list_project_missions(Home& home, const storage::User& user, const std::string& project);
/// What save_project_mission checks, without storing anything (the mission editor's live
/// drawing): the mission as it would be read from the project.
Mission check_project_mission(Home& home, const storage::User& user, const std::string& project,
                              const std::string& name, const std::string& text);
/// Validates `text` as the CLI does (one line naming the bad field), places the robots of its
/// first seed (a start region the walls leave no room in is refused), then stores it, replacing
/// a file of that name. InvalidRequest for a bad name, an oversized or malformed document;
/// nothing is written then.
ProjectMission save_project_mission(Home& home, const storage::User& user, const std::string& project,
                                    const std::string& name, const std::string& text);

}  // namespace sd::app
