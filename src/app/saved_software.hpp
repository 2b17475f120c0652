#pragma once
// Control software saved in a project under a name (the editor's "save" and "load"): one
// canonical configuration string per file, <project>/software/<name>.txt.
#include <string>
#include <vector>

#include "app/home.hpp"
#include "storage/accounts.hpp"

namespace sd::app {

struct SavedSoftware {
  std::string name, text;
};

/// The user's project's saved control software, by name; NotFound for another user's project.
std::vector<SavedSoftware> list_saved_software(Home& home, const storage::User& user, const std::string& project);
/// Saves (or replaces) it as its canonical string. InvalidRequest for a malformed name or string.
SavedSoftware save_software(Home& home, const storage::User& user, const std::string& project,
                            const std::string& name, const std::string& text);

/// Deletes it; NotFound when the project has no software so named.
void delete_saved_software(Home& home, const storage::User& user, const std::string& project, const std::string& name);

}  // namespace sd::app
