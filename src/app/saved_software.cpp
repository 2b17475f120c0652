#include "app/saved_software.hpp"

#include <algorithm>
#include <filesystem>
#include <regex>

#include "app/errors.hpp"
#include "app/quotas.hpp"
#include "app/user_files.hpp"
#include "control/config_string.hpp"
#include "core/durable_file.hpp"
#include "storage/projects.hpp"

namespace sd::app {

namespace {

std::filesystem::path folder_of(Home& home, const storage::User& user, const std::string& project) {
  return storage::Projects(home.workspace(), user).get(project).folder / "software";
}

void require_software_name(const std::string& name) {
  static const std::regex rule("[A-Za-z0-9][A-Za-z0-9._-]{0,63}");
  if (!std::regex_match(name, rule))
    throw InvalidRequest("name '" + name + "' must be 1-64 letters, digits, '.', '_' or '-', not starting with '.'");
}

}  // namespace

std::vector<SavedSoftware> list_saved_software(Home& home, const storage::User& user, const std::string& project) {
  const auto folder = folder_of(home, user, project);
  std::vector<SavedSoftware> list;
  if (!std::filesystem::is_directory(folder)) return list;
  // Every file is read under the rule for a user's own files: a link planted in the folder
  // that leads out of the user's projects, a device or a huge file is passed over, unread.
  const FileScope scope = FileScope::own_projects(home, user);
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.path().extension() != ".txt") continue;
    try {
      list.push_back({entry.path().stem().string(), scope.read(entry.path().string(), "saved control software")});
    } catch (const std::exception&) {
      continue;
    }
  }
  std::sort(list.begin(), list.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
  return list;
}

SavedSoftware save_software(Home& home, const storage::User& user, const std::string& project,
                            const std::string& name, const std::string& text) {
  require_software_name(name);
  SavedSoftware saved{name, to_config_string(parse_control_software(text))};
  const auto folder = FileScope::own_projects(home, user).writable_folder(folder_of(home, user, project),
                                                                          "the folder of saved control software");
  require_room_for_file(home, user, folder / (name + ".txt"), saved.text.size());
  replace_file_durably(folder / (name + ".txt"), saved.text, 0644, Umask::Applies);
  return saved;
}

void delete_saved_software(Home& home, const storage::User& user, const std::string& project, const std::string& name) {
  require_software_name(name);
  const auto folder = FileScope::own_projects(home, user).writable_folder(folder_of(home, user, project),
                                                                          "the folder of saved control software");
  // remove() unlinks a link itself, never what it leads to.
  if (!std::filesystem::remove(folder / (name + ".txt")))
    throw NotFound("project " + project + " has no saved control software named '" + name + "'");
}

}  // namespace sd::app
