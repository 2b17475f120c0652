#pragma once
// "A design's best", one rule for every reader (test-design and /test, compare-designs and
// /compare, the assessment, assess --project-design, export-argos of a project design, Python):
// the design's final best control software on the design's own mission, the one it was made
// for (with that mission's robot model), not whatever mission the project has been set to since.
#include <cstdint>
#include <optional>
#include <string>

#include "app/home.hpp"
#include "app/user_files.hpp"
#include "control/control_software.hpp"
#include "missions/mission.hpp"
#include "storage/designs.hpp"

namespace sd::app {

struct DesignBest {
  storage::Project project;
  storage::Design design;
  Mission mission;            // the design's own, read under the caller's scope
  ControlSoftware software;   // its best
  std::string configuration;  // the best's configuration string, as stored
};

/// Design `design` of the user's project (the active one when `project` is nullopt), or its
/// latest design with a best when `design` is nullopt. NotFound for a design the project does
/// not have, one with no best yet, or whose mission can no longer be read.
DesignBest design_best(Home& home, const storage::User& user, const std::optional<std::string>& project,
                       std::optional<std::int64_t> design, const FileScope& scope = FileScope::local());

}  // namespace sd::app
