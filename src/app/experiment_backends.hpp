#pragma once
// The one place that chooses an experiment's backend (experiment_backend.hpp): a cluster
// project's experiments go to Slurm, else to the server's threads when a server asks, else
// they run in this process.
#include <nlohmann/json_fwd.hpp>

#include <string>

#include "app/experiment_backend.hpp"

namespace sd::app {

ExperimentBackend& experiment_backend_for(const storage::Project& project, ExperimentBackend* server = nullptr);

/// Plans the launch's protocol (its files read under launch.files) and starts it on the
/// project's backend. InvalidRequest for a bad protocol, or Slurm settings in a local project.
LaunchedExperiment launch_experiment(Home& home, const storage::User& user, const ExperimentLaunch& launch,
                                     ExperimentBackend* server = nullptr);

/// Stops experiment `name` of the project through whoever runs it: scancel for its array, its
/// thread's cancel token for this server's, SIGTERM for a CLI process of this machine. Conflict
/// when it does not run or runs out of reach.
std::string stop_experiment(Home& home, const storage::User& user, const std::string& project, const std::string& name,
                            ExperimentBackend* server = nullptr);

/// What a launch answers (the page's Start and Resume, Python's run_experiment): the
/// experiment's row as experiments_document lists it, whether it resumed or had finished, the
/// plan's notes, and where it runs ("process", "server" or "slurm").
nlohmann::json launched_experiment_document(const LaunchedExperiment& launched, const nlohmann::json& row);

}  // namespace sd::app
