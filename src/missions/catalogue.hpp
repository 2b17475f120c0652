#pragma once
// Where missions come from: the built-in catalogue (compiled into the binary from the
// project's missions/ folder), the user's $SWARMDESIGN_HOME/missions, or any file path.
#include <filesystem>
#include <string>
#include <vector>

#include "missions/mission.hpp"

namespace sd {

struct MissionSummary {
  std::string name, origin, direction, title, source;
  int robots = 0;
  double duration_s = 0.0;
};

/// $SWARMDESIGN_HOME, else $XDG_DATA_HOME/swarmdesign, else ~/.local/share/swarmdesign.
std::filesystem::path swarmdesign_home();

std::vector<MissionSummary> list_missions();
bool mission_exists(const std::string& name_or_path);
/// A built-in or user mission by name, or a mission file by path.
Mission load_mission(const std::string& name_or_path);

}  // namespace sd
