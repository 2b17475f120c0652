#include "app/design_best.hpp"

#include <algorithm>

#include "app/errors.hpp"
#include "app/projects.hpp"
#include "control/config_string.hpp"

namespace sd::app {

DesignBest design_best(Home& home, const storage::User& user, const std::optional<std::string>& project,
                       std::optional<std::int64_t> design, const FileScope& scope) {
  DesignBest best;
  best.project = project_or_active(home, user, project);
  const auto designs = storage::Designs(home.workspace(), best.project).list();
  const auto chosen = std::find_if(designs.rbegin(), designs.rend(), [&](const storage::Design& d) {
    return design ? d.id == *design : d.best_config.has_value();
  });
  if (chosen == designs.rend())
    throw NotFound(design ? "project " + best.project.name + " has no design " + std::to_string(*design)
                          : "project " + best.project.name + " has no finished design yet");
  best.design = *chosen;
  if (!best.design.best_config)
    throw NotFound("design " + std::to_string(best.design.id) + " has no best control software yet");
  best.configuration = *best.design.best_config;
  best.software = parse_control_software(best.configuration);
  const std::string design_name = "design " + std::to_string(best.design.id);
  // Said as such before the scope's refusal of a missing file ("not a file of your projects").
  if (mission_file_deleted(best.design.mission, best.project))
    throw NotFound(design_name + "'s mission file was deleted, so its best cannot run on it");
  try {
    best.mission = load_requested_mission(best.design.mission, scope);
  } catch (const InvalidRequest& e) {
    throw NotFound("the mission of " + design_name + " cannot be loaded: " + e.what());
  }
  return best;
}

}  // namespace sd::app
