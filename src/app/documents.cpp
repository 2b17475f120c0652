#include "app/documents.hpp"

#include <algorithm>

#include "control/config_string.hpp"
#include "statistics/descriptive.hpp"
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
  return {{"folder", r.folder.string()},
          {"mission", r.mission},
          {"direction", r.direction},
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
          {"created", storage::format_time(d.created_at)},
          {"best_configuration", d.best_config ? json(*d.best_config) : json()},
          {"best_score", d.best_score ? json(*d.best_score) : json()}};
}

json project_document(const storage::Project& project) {
  json out{{"name", project.name},
           {"folder", project.folder.string()},
           {"location", project.cluster ? "cluster" : "local"},
           {"mission", project.mission ? json(*project.mission) : json()},
           {"budget", project.budget ? json(*project.budget) : json()},
           {"active", project.active},
           {"created", storage::format_time(project.created_at)}};
  if (project.cluster)
    out["cluster"] = {{"host", project.cluster->host},
                      {"user", project.cluster->user},
                      {"folder", project.cluster->workdir_or_default()},
                      {"binary", project.cluster->binary_or_default()}};
  return out;
}

json projects_document(const std::vector<storage::Project>& projects) {
  json list = json::array();
  for (const auto& project : projects) list.push_back(project_document(project));
  return {{"projects", list}};
}

json users_document(const UserList& users) {
  json list = json::array();
  for (const auto& user : users.users)
    list.push_back({{"name", user.name},
                    {"created", storage::format_time(user.created_at)},
                    {"signed_in", users.me && *users.me == user.id}});
  return {{"users", list}};
}

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
  return {statistics::mean(scores), statistics::median(scores)};
}

json scores_document(const Mission& mission, const ControlSoftware& software, const std::vector<std::uint64_t>& seeds,
                     const std::vector<double>& scores) {
  json runs = json::array();
  for (std::size_t i = 0; i < seeds.size(); ++i) runs.push_back({{"seed", seeds[i]}, {"score", scores[i]}});
  json out{{"mission", mission.name}, {"direction", direction_name(mission.objective.direction)},
           {"control_software", to_config_string(software)}, {"runs", runs}};
  if (seeds.size() > 1) {
    const ScoreSummary summary = summarize(scores);
    out["mean"] = summary.mean;
    out["median"] = summary.median;
  }
  return out;
}

}  // namespace sd::app
