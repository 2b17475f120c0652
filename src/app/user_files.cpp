#include "app/user_files.hpp"

#include <algorithm>

#include "app/errors.hpp"
#include "core/bounded_file.hpp"
#include "missions/catalogue.hpp"
#include "missions/start_trace.hpp"
#include "storage/workspace.hpp"

namespace sd::app {

namespace {

/// A catalogue name is a word: no separator, no control character (a NUL would cut the file
/// name the catalogue looks up short), nothing longer than a name.
bool is_catalogue_word(const std::string& name) {
  return !name.empty() && name.size() <= 128 && name.front() != '.' &&
         std::all_of(name.begin(), name.end(), [](char c) { return static_cast<unsigned char>(c) > 0x20 && c != 0x7f; });
}

}  // namespace

FileScope FileScope::own_projects(const Home& home, const storage::User& user) {
  // Links are resolved in the home's own path (where an administrator put it), never below it:
  // a link planted at users/<name>/projects would otherwise move the scope to its target. Left
  // as named, such a link leads outside the scope, and allows() refuses what lies behind it.
  // weakly: a user without a project has no folder yet, and so can name no file.
  return FileScope(std::filesystem::weakly_canonical(home.folder()) / storage::Workspace::projects_folder(user));
}

bool FileScope::allows(const std::filesystem::path& path) const {
  if (!root_) return true;
  if (!path.is_absolute()) return false;  // relative to what? A server's folder is none of the user's business.
  std::error_code ec;
  const auto real = std::filesystem::canonical(path, ec);
  return !ec && is_within(real, *root_);
}

PathRule FileScope::path_rule() const {
  if (!root_) return {};
  return [root = *root_](const std::filesystem::path& real) { return is_within(real, root); };
}

void FileScope::refuse(const std::string& path, const std::string& what) const {
  throw NotFound(what + " " + path +
                 " is not a file of your projects (here you may name the catalogue's missions and files inside "
                 "your own projects)");
}

std::string FileScope::read(const std::string& path, const std::string& what) const {
  // Asked before anything is opened, so nothing outside is even touched; asked again of what
  // was opened, so a link swapped in meanwhile is caught.
  if (!allows(path)) refuse(path, what);
  try {
    if (!root_) return read_bounded_file(path, what).text;
    return read_bounded_file(path, what, kMaxInputFileBytes,
                             [this](const std::filesystem::path& real) { return is_within(real, *root_); })
        .text;
  } catch (const FileReadError& e) {
    if (root_ && (e.problem == FileProblem::Missing || e.problem == FileProblem::Outside)) refuse(path, what);
    throw InvalidRequest(e.what());
  }
}

std::filesystem::path FileScope::writable_folder(const std::filesystem::path& path, const std::string& what) const {
  // Checked before anything is made: where the folder would be (its existing part's links
  // resolved), and no dangling link on the way, which create_directories would follow to make
  // a folder elsewhere.
  if (root_) {
    if (!is_within(std::filesystem::weakly_canonical(path), *root_)) refuse(path.string(), what);
    std::filesystem::path prefix;
    for (const auto& part : path) {
      prefix /= part;
      std::error_code ec;
      if (std::filesystem::is_symlink(prefix, ec) && !std::filesystem::exists(prefix, ec)) refuse(path.string(), what);
    }
  }
  std::filesystem::create_directories(path);
  if (!allows(path)) refuse(path.string(), what);
  return std::filesystem::canonical(path);
}

Mission load_requested_mission(const std::string& name_or_path, const FileScope& scope) {
  try {
    if (!is_mission_file(name_or_path)) {
      if (!is_catalogue_word(name_or_path))
        throw InvalidRequest("unknown mission '" + name_or_path + "' (see `swarmdesign missions`)");
      return load_mission(name_or_path);
    }
    if (scope.is_local()) return load_mission_file(name_or_path);
    const std::string text = scope.read(name_or_path, "mission file");
    try {
      return parse_mission(text, name_or_path, scope.path_rule());
    } catch (const MissionError& e) {
      throw MissionError(std::filesystem::path(name_or_path).filename().string() + ": " + e.what());
    }
  } catch (const MissionError& e) {
    throw InvalidRequest(e.what());
  }
}

Mission with_requested_arlequin_modules(const Mission& mission, const std::string& name_or_folder,
                                       const FileScope& scope) {
  if (name_or_folder.empty()) return mission;
  try {
    return with_arlequin_modules(mission, name_or_folder, scope.path_rule());
  } catch (const MissionError& e) {
    throw InvalidRequest(e.what());
  }
}

Mission with_start_from(const Mission& mission, const std::string& path) {
  if (path.empty()) return mission;
  try {
    return started_from_trace(mission, path);
  } catch (const MissionError& e) {
    throw InvalidRequest(e.what());
  }
}

}  // namespace sd::app
