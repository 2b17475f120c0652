#include "app/home_backup.hpp"

#include <nlohmann/json.hpp>

#include <set>
#include <system_error>

#include "storage/sqlite.hpp"

namespace sd::app {

namespace fs = std::filesystem;

namespace {

/// SQLite's own verdict on a database: empty when "ok".
std::string integrity(storage::Database& db) {
  std::string verdict;
  storage::Statement s = db.prepare("PRAGMA integrity_check");
  while (s.step()) {
    const std::string line = s.text(0);
    if (line != "ok") verdict += (verdict.empty() ? "" : "; ") + line;
  }
  return verdict;
}

/// Replaces the old home's folder by the new one at the start of every stored mission path and
/// in every protocol (mission files are stored by absolute path, in the home's project folders).
void relocate(storage::Database& db, const std::string& from, const std::string& to) {
  const std::string old_prefix = from + "/", new_prefix = to + "/";
  for (const char* column : {"projects.mission", "designs.mission", "experiment_designs.mission"}) {
    const std::string c(column);
    const std::string table = c.substr(0, c.find('.')), field = c.substr(c.find('.') + 1);
    db.prepare("UPDATE " + table + " SET " + field + " = ?2 || substr(" + field + ", length(?1) + 1) WHERE substr(" +
               field + ", 1, length(?1)) = ?1")
        .bind(1, old_prefix)
        .bind(2, new_prefix)
        .run();
  }
  db.prepare("UPDATE experiments SET protocol = replace(protocol, ?1, ?2)").bind(1, old_prefix).bind(2, new_prefix).run();
}

}  // namespace

storage::HomeArchive back_up_home(Home& home, const fs::path& archive) {
  return storage::archive_home(home.folder(), archive);
}

storage::HomeArchive restore_home(const fs::path& archive, const fs::path& folder) {
  storage::HomeArchive restored = storage::restore_home(archive, folder);
  const std::string to = fs::absolute(folder).lexically_normal().string();
  if (restored.home.empty() || restored.home == to) return restored;
  Home home(folder);  // migrated to this version's schema, as any command opens it
  storage::Database& db = home.workspace().database();
  relocate(db, restored.home, to);
  // Each design's own database names its mission the same way (its meta table).
  storage::Statement designs = db.prepare("SELECT path FROM designs");
  while (designs.step()) {
    const fs::path file = home.workspace().resolve(designs.text(0)) / "design.db";
    if (!fs::is_regular_file(file)) continue;
    storage::Database design(file, false);
    design.prepare("UPDATE meta SET value = replace(value, ?1, ?2)").bind(1, restored.home + "/").bind(2, to + "/").run();
  }
  return restored;
}

HomeCheck check_home(Home& home) {
  HomeCheck out;
  storage::Database& db = home.workspace().database();
  if (const std::string verdict = integrity(db); !verdict.empty()) out.problems.push_back({"database", "swarmdesign.db: " + verdict});
  ++out.databases;
  std::set<fs::path> named;  // folders the database names, relative to the home
  storage::Statement users = db.prepare("SELECT count(*) FROM users");
  if (users.step()) out.users = static_cast<int>(users.integer(0));
  storage::Statement projects = db.prepare("SELECT path FROM projects");
  while (projects.step()) {
    ++out.projects;
    named.insert(fs::path(projects.text(0)).lexically_normal());
  }
  for (const char* sql : {"SELECT path FROM designs", "SELECT path FROM experiments"}) {
    storage::Statement rows = db.prepare(sql);
    while (rows.step()) {
      const fs::path relative = fs::path(rows.text(0)).lexically_normal();
      named.insert(relative);
      if (std::string(sql).find("designs") != std::string::npos) ++out.designs;
    }
  }
  for (const fs::path& relative : named) {
    const fs::path folder = home.workspace().resolve(relative);
    std::error_code ec;
    if (!fs::is_directory(fs::symlink_status(folder, ec))) {
      out.problems.push_back({"missing-folder", relative.generic_string()});
      continue;
    }
    const fs::path db_file = folder / "design.db";
    if (fs::is_regular_file(fs::symlink_status(db_file, ec))) {
      storage::Database design(db_file, false);
      ++out.databases;
      if (const std::string verdict = integrity(design); !verdict.empty())
        out.problems.push_back({"database", (relative / "design.db").generic_string() + ": " + verdict});
    }
  }
  // Every project and design folder on disk must be one the database names.
  const fs::path users_folder = home.folder() / "users";
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(users_folder, ec); !ec && it != fs::recursive_directory_iterator(); ++it) {
    const fs::path relative = it->path().lexically_relative(home.folder());
    if (it->is_symlink()) {
      out.problems.push_back({"link", relative.generic_string()});
      continue;
    }
    if (!it->is_directory()) continue;
    // users/<user>/projects/<project> and .../designs/<id>, .../experiments/<name>
    std::vector<std::string> parts;
    for (const auto& p : relative) parts.push_back(p.string());
    const bool project = parts.size() == 4 && parts[2] == "projects";
    const bool design = parts.size() == 6 && parts[2] == "projects" && (parts[4] == "designs");
    if ((project || design) && !named.count(relative)) out.problems.push_back({"orphan-folder", relative.generic_string()});
  }
  for (auto it = fs::directory_iterator(home.folder(), ec); !ec && it != fs::directory_iterator(); ++it)
    if (it->is_symlink()) out.problems.push_back({"link", it->path().lexically_relative(home.folder()).generic_string()});
  return out;
}

nlohmann::json home_check_document(const HomeCheck& check) {
  nlohmann::json problems = nlohmann::json::array();
  for (const HomeProblem& p : check.problems) problems.push_back({{"kind", p.kind}, {"what", p.what}});
  return {{"ok", check.ok()},      {"users", check.users},         {"projects", check.projects},
          {"designs", check.designs}, {"databases", check.databases}, {"problems", problems}};
}

nlohmann::json home_archive_document(const storage::HomeArchive& archive, const fs::path& file) {
  return {{"archive", fs::absolute(file).string()}, {"files", archive.files.size()}, {"bytes", archive.bytes},
          {"from", archive.home}};
}

}  // namespace sd::app
