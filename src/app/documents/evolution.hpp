#pragma once
// The document of an EvoStick evolution for a mission (`evostick --mission --json`, and an
// experiment's EvoStick design, whose convergence is read from its history). A module's
// evolution has data/arlequin's format (evostick/weight_document).
#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <string>

#include "evostick/evolution.hpp"
#include "missions/mission.hpp"

namespace sd::app {

/// `budget` > 0: the budget the generations were derived from.
nlohmann::json mission_evolution_document(const Mission& mission, const evostick::Settings& settings,
                                          const evostick::Result& result, const std::string& control_software,
                                          std::int64_t budget);

}  // namespace sd::app
