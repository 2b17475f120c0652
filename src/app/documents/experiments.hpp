#pragma once
// The documents of experiments: a plan with its duration estimate (`experiment --dry-run
// --json`) and the experiments of a project with their progress (status, the web monitor).
// The types are experiment_job's, which includes this file so its users get both.
#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace sd::app {

struct PlannedExperiment;
struct DurationEstimate;
struct ExperimentProgress;
struct ClusterCollection;

/// `estimate` may be null (no measure taken).
nlohmann::json plan_document(const PlannedExperiment& plan, const DurationEstimate* estimate);
nlohmann::json experiments_document(const std::vector<ExperimentProgress>& experiments);
/// What collect_cluster_experiments did, and the project's experiments after it (`collect
/// --json`, Python's Account.collect).
nlohmann::json collection_document(const std::string& project, const ClusterCollection& collection,
                                   const std::vector<ExperimentProgress>& experiments);

}  // namespace sd::app
