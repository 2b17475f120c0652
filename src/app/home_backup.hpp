#pragma once
// A lab's home kept safe (issue #56): backed up while the server and designs run, restored into
// a new home (on this machine or another: the paths it holds follow it), and checked.
#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "app/home.hpp"
#include "storage/home_archive.hpp"

namespace sd::app {

/// The home into `archive` (storage/home_archive.hpp says how it stays consistent while in use).
storage::HomeArchive back_up_home(Home& home, const std::filesystem::path& archive);

/// `archive` into `folder` (new or empty), every file checked against the manifest first; the
/// mission files the database and each design name by the old home's path are renamed into the
/// new one, so its designs resume there. storage::BackupError for a damaged or foreign archive.
storage::HomeArchive restore_home(const std::filesystem::path& archive, const std::filesystem::path& folder);

struct HomeProblem {
  std::string kind;  // database | missing-folder | orphan-folder | link
  std::string what;  // a path relative to the home, or the database's own words
};

struct HomeCheck {
  int users = 0, projects = 0, designs = 0, databases = 0;
  std::vector<HomeProblem> problems;
  bool ok() const { return problems.empty(); }
};

/// The accounts database's and every design database's integrity check, every folder the
/// database names present, no project or design folder it does not name, and no link anywhere
/// under the home (the server follows none, so one there was planted).
HomeCheck check_home(Home& home);

nlohmann::json home_check_document(const HomeCheck& check);
nlohmann::json home_archive_document(const storage::HomeArchive& archive, const std::filesystem::path& file);

}  // namespace sd::app
