#include "app/project_missions.hpp"

#include <algorithm>
#include <regex>

#include "app/errors.hpp"
#include "app/quotas.hpp"
#include "app/user_files.hpp"
#include "control/config_string.hpp"
#include "core/bounded_file.hpp"
#include "core/durable_file.hpp"
#include "evaluation/simulation.hpp"
#include "missions/mission.hpp"
#include "storage/projects.hpp"

namespace sd::app {

namespace {

std::filesystem::path folder_of(Home& home, const storage::User& user, const std::string& project) {
  return storage::Projects(home.workspace(), user).get(project).folder / "missions";
}

/// A mission can be parsed and still be unusable: walls that leave the start region no room
/// for its robots fail only when a run places them. Placing them once here says so at upload.
void require_room_for_robots(const Mission& mission, const std::string& name) {
  const ControlSoftware stop = parse_control_software("--fsm-config --nstates 1 --s0 1");
  try {
    Simulation simulation(mission, stop);
    simulation.reset(1);
  } catch (const std::exception& e) {
    throw InvalidRequest("mission '" + name + "': " + e.what());
  }
}

}  // namespace

std::vector<ProjectMission> list_project_missions(Home& home, const storage::User& user, const std::string& project) {
  const auto folder = folder_of(home, user, project);
  std::vector<ProjectMission> list;
  if (!std::filesystem::is_directory(folder)) return list;
  const FileScope scope = FileScope::own_projects(home, user);
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    // Only regular files the user's rule lets them use: a link planted here that leads out, or
    // a second name of someone else's file, is not listed (and would be refused if named).
    if (entry.path().extension() != ".json" || !entry.is_regular_file() || entry.is_symlink()) continue;
    if (!scope.allows(entry.path())) continue;
    list.push_back({entry.path().stem().string(), entry.path()});
  }
  std::sort(list.begin(), list.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return list;
}

ProjectMission save_project_mission(Home& home, const storage::User& user, const std::string& project,
                                    const std::string& name, const std::string& text) {
  check_project_mission(home, user, project, name, text);
  const auto folder = FileScope::own_projects(home, user).writable_folder(folder_of(home, user, project),
                                                                          "the project's missions folder");
  const auto file = folder / (name + ".json");
  require_room_for_file(home, user, file, text.size());
  replace_file_durably(file, text, 0600, Umask::Applies);
  return {name, file};
}

Mission check_project_mission(Home& home, const storage::User& user, const std::string& project,
                              const std::string& name, const std::string& text) {
  static const std::regex rule("[A-Za-z0-9][A-Za-z0-9_-]{0,63}");
  if (!std::regex_match(name, rule))
    throw InvalidRequest("mission name '" + name.substr(0, 80) +
                         "' must be 1-64 letters, digits, '_' or '-', not starting with '_' or '-'");
  if (text.size() > kMaxInputFileBytes)
    throw InvalidRequest("mission '" + name + "' is larger than 1 MiB");
  const FileScope scope = FileScope::own_projects(home, user);
  const auto wanted_folder = folder_of(home, user, project);
  Mission mission;
  try {
    // Read as it will be stored (an Arlequin folder it names resolves next to it), under the
    // user's rule for every file it names.
    mission = parse_mission(text, (wanted_folder / (name + ".json")).string(), scope.path_rule());
  } catch (const MissionError& e) {
    throw InvalidRequest(std::string("mission '") + name + "': " + e.what());
  }
  require_room_for_robots(mission, name);
  return mission;
}

}  // namespace sd::app
