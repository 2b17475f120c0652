#pragma once
// The documents of a design: its final report, its live and stored progress, its race log and
// convergence, its row in a project, its Slurm job, and `status` (all of those a project's
// design has), plus the one document read back: the stored progress a cluster job prints.
#include <nlohmann/json_fwd.hpp>

#include <vector>

#include "app/design_backends.hpp"
#include "app/design_job.hpp"
#include "design/iterated_race.hpp"
#include "storage/cluster_jobs.hpp"
#include "storage/design_status.hpp"
#include "storage/designs.hpp"

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
/// A cluster project's design: its Slurm job (id, folder, settings, state, note).
nlohmann::json cluster_job_document(const storage::ClusterJob& job);
/// `status`: the project's current or last design, its progress, its Slurm job, and with
/// `complete` its race log and convergence.
nlohmann::json status_document(const DesignStatus& status, StatusDetail detail);
/// storage::DesignProgress back from stored_progress_document (a cluster's `design-status
/// --json`, read by the cluster backend); std::runtime_error naming the field when damaged.
storage::DesignProgress stored_progress_from_document(const nlohmann::json& document);

}  // namespace sd::app
