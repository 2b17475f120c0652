#pragma once
// Where SwarmDesign keeps its state — the accounts database, the users' projects and designs,
// the user's own missions — decided by one rule, so that all of them land in the same folder.
#include <filesystem>

namespace sd {

/// $SWARMDESIGN_HOME if set (made absolute); else $XDG_DATA_HOME/swarmdesign when that is
/// absolute, as the XDG spec requires; else ~/.local/share/swarmdesign. Always absolute.
std::filesystem::path swarmdesign_home();

}  // namespace sd
