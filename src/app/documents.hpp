#pragma once
// The JSON documents of the application's objects — a design's report, its progress and race
// log, a project, the missions, a batch of scores, the users — made in one place, so that the
// CLI's --json, a web server's responses and its WebSocket/SSE stream send the same documents.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <vector>

#include "app/accounts.hpp"
#include "app/design_job.hpp"
#include "design/iterated_race.hpp"
#include "missions/catalogue.hpp"
#include "storage/design_status.hpp"
#include "storage/designs.hpp"
#include "storage/projects.hpp"

namespace sd::app {

nlohmann::json design_report_document(const DesignReport& report);
/// A race step as a design reports it live (costs turned into the mission's scores).
nlohmann::json progress_document(const design::Progress& progress, bool maximise);
/// A design's progress as read from its design.db (status).
nlohmann::json stored_progress_document(const storage::DesignProgress& progress);
nlohmann::json race_log_document(const std::vector<storage::RaceRecord>& log);
/// [{"iteration","runs_used","best_id","best_score"}]: the best elite's mean over all its runs so far.
nlohmann::json convergence_document(const std::vector<storage::ConvergencePoint>& points);
nlohmann::json design_row_document(const storage::Design& design);

nlohmann::json project_document(const storage::Project& project);
nlohmann::json projects_document(const std::vector<storage::Project>& projects);
nlohmann::json users_document(const UserList& users);

nlohmann::json missions_document(const std::vector<MissionSummary>& missions);
nlohmann::json mission_document(const Mission& mission);

struct ScoreSummary {
  double mean = 0.0, median = 0.0;
};
/// R's mean and median of the scores; throws std::invalid_argument on none (statistics/descriptive).
ScoreSummary summarize(const std::vector<double>& scores);
nlohmann::json scores_document(const Mission& mission, const ControlSoftware& software,
                               const std::vector<std::uint64_t>& seeds, const std::vector<double>& scores);

}  // namespace sd::app
