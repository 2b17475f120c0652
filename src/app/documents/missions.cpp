#include "app/documents/missions.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <numeric>

#include "app/documents/reality.hpp"
#include "control/config_string.hpp"

namespace sd::app {

using nlohmann::json;

json missions_document(const std::vector<MissionSummary>& missions) {
  json out = json::array();
  for (const auto& m : missions)
    out.push_back({{"name", m.name}, {"title", m.title}, {"origin", m.origin}, {"robots", m.robots},
                   {"duration_s", m.duration_s}, {"direction", m.direction}, {"source", m.source}});
  return out;
}

json mission_document(const Mission& m) {
  return {{"name", m.name},
          {"title", m.title},
          {"origin", m.origin},
          {"description", m.description},
          {"robots", m.robots},
          {"duration_s", m.duration_s},
          {"ticks", m.ticks},
          {"walls", m.arena.walls.size()},
          {"floor_patches", m.arena.floor_patches.size()},
          {"lights", m.arena.lights.size()},
          {"objective", m.objective.type},
          {"direction", direction_name(m.objective.direction)},
          {"source", m.source}};
}

ScoreSummary summarize(const std::vector<double>& scores) {
  if (scores.empty()) return {};
  std::vector<double> sorted = scores;
  std::sort(sorted.begin(), sorted.end());
  const std::size_t n = sorted.size();
  const double median = n % 2 ? sorted[n / 2] : 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]);
  return {std::accumulate(scores.begin(), scores.end(), 0.0) / static_cast<double>(n), median};
}

json scores_document(const Mission& mission, const ControlSoftware& software, const std::vector<std::uint64_t>& seeds,
                     const std::vector<double>& scores) {
  json runs = json::array();
  for (std::size_t i = 0; i < seeds.size(); ++i) runs.push_back({{"seed", seeds[i]}, {"score", scores[i]}});
  json out{{"mission", mission.name}, {"direction", direction_name(mission.objective.direction)},
           {"control_software", to_config_string(software)}, {"runs", runs}, {"robot", robot_model_document(mission.robot)}};
  if (seeds.size() > 1) {
    const ScoreSummary summary = summarize(scores);
    out["mean"] = summary.mean;
    out["median"] = summary.median;
  }
  return out;
}

}  // namespace sd::app
