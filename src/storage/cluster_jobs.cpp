#include "storage/cluster_jobs.hpp"

#include <nlohmann/json.hpp>

#include "storage/clock.hpp"
#include "storage/errors.hpp"

namespace sd::storage {

ClusterJobs::ClusterJobs(Workspace& workspace, Project project) : workspace_(workspace), project_(std::move(project)) {}

void ClusterJobs::submitted(std::int64_t design_id, const std::string& job_id, const std::string& folder,
                            const std::string& settings) {
  Database& db = workspace_.database();
  Transaction transaction(db);
  auto owned = db.prepare("SELECT 1 FROM designs WHERE id = ? AND project_id = ?");
  owned.bind(1, design_id).bind(2, project_.id);
  if (!owned.step()) throw NotFound("no design " + std::to_string(design_id) + " in project " + project_.name);
  db.prepare("INSERT INTO cluster_jobs (design_id, job_id, folder, settings, slurm_state, note, submitted_at) "
             "VALUES (?1, nullif(?2, ''), ?3, ?4, nullif(?6, ''), NULL, ?5) ON CONFLICT (design_id) DO UPDATE SET "
             "job_id = nullif(?2, ''), folder = ?3, settings = ?4, slurm_state = nullif(?6, ''), note = NULL, submitted_at = ?5, "
             "checked_at = NULL")
      .bind(1, design_id).bind(2, job_id).bind(3, folder).bind(4, settings).bind(5, unix_now())
      .bind(6, job_id.empty() ? "" : "PENDING").run();
  transaction.commit();
}

void ClusterJobs::observed(std::int64_t design_id, const std::string& slurm_state, const std::string& note) {
  auto update = workspace_.database().prepare(
      "UPDATE cluster_jobs SET slurm_state = coalesce(nullif(?1, ''), slurm_state), note = nullif(?2, ''), "
      "checked_at = ?3 WHERE design_id = ?4 AND design_id IN (SELECT id FROM designs WHERE project_id = ?5)");
  update.bind(1, slurm_state).bind(2, note).bind(3, unix_now()).bind(4, design_id).bind(5, project_.id).run();
}

std::optional<ClusterJob> ClusterJobs::find(std::int64_t design_id) {
  auto query = workspace_.database().prepare(
      "SELECT j.design_id, coalesce(j.job_id, ''), j.folder, j.settings, coalesce(j.slurm_state, ''), coalesce(j.note, ''), "
      "j.submitted_at, coalesce(j.checked_at, 0) FROM cluster_jobs j JOIN designs d ON d.id = j.design_id "
      "WHERE j.design_id = ? AND d.project_id = ?");
  query.bind(1, design_id).bind(2, project_.id);
  if (!query.step()) return std::nullopt;
  return ClusterJob{query.integer(0), query.text(1), query.text(2), query.text(3),
                    query.text(4),    query.text(5), query.integer(6), query.integer(7)};
}

void ClusterJobs::array_submitted(std::int64_t experiment_id, const std::string& job_id, const std::string& folder,
                                  const std::string& settings, const std::vector<std::int64_t>& tasks) {
  Database& db = workspace_.database();
  Transaction transaction(db);
  auto owned = db.prepare("SELECT 1 FROM experiments WHERE id = ? AND project_id = ?");
  owned.bind(1, experiment_id).bind(2, project_.id);
  if (!owned.step()) throw NotFound("no experiment " + std::to_string(experiment_id) + " in project " + project_.name);
  const std::string list = nlohmann::json(tasks).dump();
  db.prepare("INSERT INTO cluster_array_jobs (experiment_id, job_id, folder, settings, tasks, slurm_state, note, "
             "submitted_at) VALUES (?1, nullif(?2, ''), ?3, ?4, ?5, nullif(?6, ''), NULL, ?7) "
             "ON CONFLICT (experiment_id) DO UPDATE SET job_id = nullif(?2, ''), folder = ?3, settings = ?4, "
             "tasks = ?5, slurm_state = nullif(?6, ''), note = NULL, submitted_at = ?7, checked_at = NULL")
      .bind(1, experiment_id).bind(2, job_id).bind(3, folder).bind(4, settings).bind(5, list)
      .bind(6, job_id.empty() ? "" : "PENDING").bind(7, unix_now()).run();
  transaction.commit();
}

void ClusterJobs::array_observed(std::int64_t experiment_id, const std::string& slurm_state, const std::string& note) {
  workspace_.database()
      .prepare("UPDATE cluster_array_jobs SET slurm_state = coalesce(nullif(?1, ''), slurm_state), note = nullif(?2, ''), "
               "checked_at = ?3 WHERE experiment_id = ?4 AND experiment_id IN "
               "(SELECT id FROM experiments WHERE project_id = ?5)")
      .bind(1, slurm_state).bind(2, note).bind(3, unix_now()).bind(4, experiment_id).bind(5, project_.id).run();
}

std::optional<ClusterArrayJob> ClusterJobs::find_array(std::int64_t experiment_id) {
  auto query = workspace_.database().prepare(
      "SELECT j.experiment_id, coalesce(j.job_id, ''), j.folder, j.settings, j.tasks, coalesce(j.slurm_state, ''), "
      "coalesce(j.note, ''), j.submitted_at FROM cluster_array_jobs j JOIN experiments e ON e.id = j.experiment_id "
      "WHERE j.experiment_id = ? AND e.project_id = ?");
  query.bind(1, experiment_id).bind(2, project_.id);
  if (!query.step()) return std::nullopt;
  ClusterArrayJob job{query.integer(0), query.text(1), query.text(2), query.text(3), {}, query.text(5), query.text(6),
                      query.integer(7)};
  job.tasks = nlohmann::json::parse(query.text(4)).get<std::vector<std::int64_t>>();
  return job;
}

}  // namespace sd::storage
