#include "app/documents/design.hpp"

#include <nlohmann/json.hpp>

#include "core/json_integer.hpp"
#include "storage/clock.hpp"

namespace sd::app {

using nlohmann::json;

namespace {
json elite_document(const EliteReport& e) {
  return {{"id", e.id}, {"configuration", e.configuration}, {"mean_score", e.mean_score}, {"evaluations", e.evaluations}};
}

json configuration_score(const storage::ConfigurationScore& c) {
  return {{"id", c.id}, {"configuration", c.command_line}, {"mean_score", c.mean_score}, {"runs", c.runs}};
}
}  // namespace


json design_report_document(const DesignReport& r) {
  json elites = json::array();
  for (const auto& e : r.elites) elites.push_back(elite_document(e));
  const double overhead = r.wall_seconds > 0 ? (r.wall_seconds - r.evaluation_seconds) / r.wall_seconds : 0.0;
  json out = {{"folder", r.folder.string()},
          {"mission", r.mission},
          {"direction", r.direction},
          {"method", r.method},
          {"budget", r.budget},
          {"seed", r.seed},
          {"architectures", r.architectures},
          {"flavours", r.flavours},
          {"resumed", r.resumed},
          {"experiments_used", r.experiments_used},
          {"iterations", r.iterations},
          {"finish_reason", r.finish_reason},
          {"best", elites.empty() ? json() : elites.front()},
          {"elites", elites},
          {"timing",
           {{"wall_s", r.wall_seconds}, {"evaluation_s", r.evaluation_seconds}, {"optimiser_overhead", overhead},
            {"threads", r.threads}}}};
  // A robust design says where its instances ran; its mean scores are over those models.
  if (!r.pseudo_reality.empty())
    out["pseudo_reality"] = {{"reference", r.pseudo_reality}, {"samples", r.pseudo_reality_samples}};
  return out;
}

json progress_document(const design::Progress& p, bool maximise) {
  json out{{"iteration", p.iteration},   {"total_iterations", p.nb_iterations},
           {"experiments_used", p.experiments_used}, {"budget", p.budget},
           {"alive", p.alive},           {"race_configurations", p.race_configurations},
           {"instances", p.task}};
  if (p.best_id > 0) out["best"] = {{"id", p.best_id}, {"mean_score", maximise ? -p.best_mean : p.best_mean}};
  return out;
}

json stored_progress_document(const storage::DesignProgress& p) {
  json out{{"started", p.started},
           {"phase", p.phase},
           {"iteration", p.iteration},
           {"total_iterations", p.nb_iterations},
           {"experiments_used", p.experiments_used},
           {"remaining_budget", p.budget - p.experiments_used},
           {"race_budget", p.race_budget},
           {"race_configurations", p.race_configurations},
           {"race_alive", p.race_alive},
           {"configurations_sampled", p.configurations_sampled},
           {"best", p.best ? configuration_score(*p.best) : json()}};
  json elites = json::array();  // each over all its runs, as "best" (the race log's means are per race)
  for (const auto& e : p.elites) elites.push_back(configuration_score(e));
  out["elites"] = elites;
  if (!p.finish_reason.empty()) out["finish_reason"] = p.finish_reason;
  return out;
}

json race_log_document(const std::vector<storage::RaceRecord>& log) {
  json races = json::array();
  for (const auto& r : log) {
    json instances = json::array(), members = json::array();
    for (const auto& [position, seed] : r.instances) instances.push_back({{"position", position}, {"seed", seed}});
    for (const auto& m : r.members) {
      json member = configuration_score(m.configuration);
      member["elite"] = m.elite;
      member["eliminated_after"] = m.eliminated_after ? json(*m.eliminated_after) : json();
      members.push_back(std::move(member));
    }
    races.push_back({{"iteration", r.iteration}, {"race_budget", r.race_budget}, {"instances", instances},
                     {"configurations", members}, {"elites", r.elites}});
  }
  return races;
}

json convergence_document(const std::vector<storage::ConvergencePoint>& points) {
  json out = json::array();
  for (const auto& p : points)
    out.push_back({{"iteration", p.iteration}, {"runs_used", p.runs_used}, {"best_id", p.best_id}, {"best_score", p.best_score}});
  return out;
}

json design_row_document(const storage::Design& d) {
  return {{"id", d.id},
          {"state", storage::to_string(d.state)},
          {"pid", d.pid},
          {"owner", d.owner},
          {"folder", d.folder.string()},
          {"mission", d.mission},
          {"budget", d.budget},
          {"seed", d.seed},
          {"architectures", d.architectures},
          {"flavours", d.flavours},
          {"method", d.method},
          {"created", storage::format_time(d.created_at)},
          {"best_configuration", d.best_config ? json(*d.best_config) : json()},
          {"best_score", d.best_score ? json(*d.best_score) : json()}};
}

json cluster_job_document(const storage::ClusterJob& job) {
  json out{{"job_id", job.job_id.empty() ? json() : json(job.job_id)},
           {"folder", job.folder},
           {"settings", job.settings.empty() ? json::object() : json::parse(job.settings)},
           {"slurm_state", job.slurm_state.empty() ? json() : json(job.slurm_state)},
           {"note", job.note.empty() ? json() : json(job.note)}};
  return out;
}

namespace {

/// A count of the status document a cluster job wrote: range-checked, as the file comes from
/// the cluster's disk (a damaged one fails in one line, never as undefined behaviour).
template <class Int>
Int integer(const json& object, const char* key) {
  return checked_json_integer<Int>(object.at(key), std::string("the cluster's status document: ") + key);
}

}  // namespace

storage::DesignProgress stored_progress_from_document(const json& d) {
  storage::DesignProgress p;
  p.started = d.at("started").get<bool>();
  p.phase = d.at("phase").get<std::string>();
  p.iteration = integer<int>(d, "iteration");
  p.nb_iterations = integer<int>(d, "total_iterations");
  p.experiments_used = integer<std::int64_t>(d, "experiments_used");
  p.budget = p.experiments_used + integer<std::int64_t>(d, "remaining_budget");
  p.race_budget = integer<std::int64_t>(d, "race_budget");
  p.race_configurations = integer<int>(d, "race_configurations");
  // A cluster running an older binary writes no count of the alive: all of them, as it began.
  p.race_alive = d.contains("race_alive") ? integer<int>(d, "race_alive") : p.race_configurations;
  p.configurations_sampled = integer<std::int64_t>(d, "configurations_sampled");
  if (const auto& b = d.at("best"); !b.is_null())
    p.best = storage::ConfigurationScore{integer<int>(b, "id"), b.at("configuration").get<std::string>(),
                                         b.at("mean_score").get<double>(), integer<std::int64_t>(b, "runs")};
  p.finish_reason = d.value("finish_reason", "");
  return p;
}


nlohmann::json status_document(const DesignStatus& status, StatusDetail detail) {
  if (!status.design) return {{"project", status.project.name}, {"design", nullptr}};
  nlohmann::json out{{"project", status.project.name},
                     {"design", design_row_document(*status.design)},
                     {"progress", stored_progress_document(status.progress)}};
  if (status.cluster_job) out["cluster_job"] = cluster_job_document(*status.cluster_job);
  if (detail != StatusDetail::progress) out["convergence"] = convergence_document(status.convergence);
  if (detail == StatusDetail::complete) out["race_log"] = race_log_document(status.race_log);
  return out;
}

}  // namespace sd::app
