#include "app/documents/evolution.hpp"

#include "evostick/weight_document.hpp"

namespace sd::app {

nlohmann::json mission_evolution_document(const Mission& mission, const evostick::Settings& settings,
                                          const evostick::Result& result, const std::string& control_software,
                                          std::int64_t budget) {
  nlohmann::json doc{{"mission", mission.name},
                     {"direction", direction_name(mission.objective.direction)},
                     {"settings", evostick::settings_json(settings)},
                     {"runs", result.runs},
                     {"control_software", control_software},
                     {"mean", result.best_mean},
                     {"weights_digest", evostick::digest_text(evostick::weight_digest(result.best))},
                     {"history", evostick::history_json(result.history)},
                     {"weights", evostick::weights_json(result.best)}};
  if (budget > 0) doc["budget"] = budget;
  return doc;
}

}  // namespace sd::app
