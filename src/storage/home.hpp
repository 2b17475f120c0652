#pragma once
// Where SwarmDesign keeps its state: the database and the users' workspaces.
#include <filesystem>

namespace sd::storage {

/// $SWARMDESIGN_HOME if set; else $XDG_DATA_HOME/swarmdesign (when absolute, as the XDG
/// spec requires); else ~/.local/share/swarmdesign. Always an absolute path.
std::filesystem::path swarmdesign_home();

/// The accounts and projects database inside a SwarmDesign home.
inline std::filesystem::path database_path(const std::filesystem::path& home) { return home / "swarmdesign.db"; }

}  // namespace sd::storage
