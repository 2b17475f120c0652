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

/// The one rule for "is this mission reference a file?": it has a '/' or ends in ".json";
/// anything else is a catalogue name.
bool is_mission_file(const std::string& name_or_path);
/// A mission as it is stored for later (a project's mission, a design's, an evolution's): a
/// catalogue name as given, a mission file by absolute path, so that it reads the same file
/// from whatever folder the design is resumed.
std::string mission_reference(const std::string& name_or_path);

std::vector<MissionSummary> list_missions();
bool mission_exists(const std::string& name_or_path);
/// A built-in or user mission by name, or a mission file by path.
Mission load_mission(const std::string& name_or_path);

}  // namespace sd
