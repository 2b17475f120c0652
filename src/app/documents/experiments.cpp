#include "app/documents/experiments.hpp"

#include <nlohmann/json.hpp>

#include "app/cluster_experiments.hpp"
#include "app/experiment_job.hpp"
#include "experiments/protocol.hpp"

namespace sd::app {

nlohmann::json plan_document(const PlannedExperiment& plan, const DurationEstimate* estimate) {
  nlohmann::json designs = nlohmann::json::array();
  for (const auto& d : plan.designs)
    designs.push_back({{"mission", d.mission}, {"condition", d.condition}, {"replicate", d.replicate}, {"method", d.method},
                       {"architectures", d.architectures}, {"flavours", d.flavours}, {"budget", d.budget}, {"seed", d.seed}});
  nlohmann::json doc{{"protocol", experiments::to_json(plan.protocol)}, {"designs", designs}, {"notes", plan.notes},
                     {"design_runs", plan.design_runs}, {"assessment_runs", plan.assessment_runs}};
  if (estimate) {
    nlohmann::json missions = nlohmann::json::array();
    for (const auto& m : estimate->missions)
      missions.push_back({{"mission", m.mission}, {"runs", m.runs}, {"seconds_per_run", m.seconds_per_run}});
    doc["estimate"] = {{"threads", estimate->threads}, {"seconds", estimate->seconds}, {"missions", missions}};
  }
  return doc;
}

nlohmann::json experiments_document(const std::vector<ExperimentProgress>& experiments) {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& e : experiments) {
    nlohmann::json item{{"name", e.experiment.name},
                        {"state", storage::to_string(e.experiment.state)},
                        {"designs", e.designs},
                        {"designs_done", e.designs_done}};
    // Whether its designs are also assessed in pseudo-realities (and in how many samples).
    const auto protocol = nlohmann::json::parse(e.experiment.protocol, nullptr, false);
    if (protocol.is_object() && protocol.contains("pseudo_reality"))
      item["pseudo_reality"] = {{"spec", protocol["pseudo_reality"].value("spec", "")},
                                {"samples", protocol["pseudo_reality"].value("samples", 0)}};
    if (e.current)
      item["current"] = {{"mission", mission_label(e.current->plan.mission)},     {"condition", e.current->plan.condition},
                         {"replicate", e.current->plan.replicate}, {"stage", storage::to_string(e.current->stage)},
                         {"budget", e.current->plan.budget},       {"folder", e.current->folder.string()}};
    if (e.current && e.current_race && e.current_race->started) {
      item["current"]["runs_used"] = e.current_race->experiments_used;
      item["current"]["iteration"] = e.current_race->iteration;
      if (e.current_race->best) item["current"]["best_score"] = e.current_race->best->mean_score;
    }
    list.push_back(std::move(item));
  }
  return list;
}

nlohmann::json collection_document(const std::string& project, const ClusterCollection& collection,
                                   const std::vector<ExperimentProgress>& experiments) {
  return {{"project", project},
          {"experiments", collection.experiments},
          {"designs_home", collection.designs_home},
          {"still_running", collection.still_running},
          {"progress", experiments_document(experiments)}};
}

}  // namespace sd::app
