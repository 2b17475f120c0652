#pragma once
// The documents of missions and of scores on them: the catalogue, one mission, a batch of scores.
#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <vector>

#include "control/control_software.hpp"
#include "missions/catalogue.hpp"

namespace sd::app {

nlohmann::json missions_document(const std::vector<MissionSummary>& missions);
nlohmann::json mission_document(const Mission& mission);

struct ScoreSummary {
  double mean = 0.0, median = 0.0;
};
ScoreSummary summarize(const std::vector<double>& scores);
nlohmann::json scores_document(const Mission& mission, const ControlSoftware& software,
                               const std::vector<std::uint64_t>& seeds, const std::vector<double>& scores);

}  // namespace sd::app
