#pragma once
// Continuing runs that an earlier process kept (a design's race, an EvoStick evolution): they
// may only go on with the mission and the simulator they started with, or one race or one
// population would mix runs of two missions or two simulators.
#include <string>

#include "app/user_files.hpp"
#include "missions/catalogue.hpp"

namespace sd::app {

struct ResumeCheck {
  Mission mission;      // loaded from the stored reference (when it could be)
  std::string refusal;  // one line saying why the runs cannot go on; empty when they can
};

/// Why runs of a swarm of `robots` kept under `stored_results_version` cannot go on in this
/// build, or "" when they can; `what` names them ("the evolution in FILE").
std::string results_version_refusal(const std::string& what, int stored_results_version, int robots);

/// The mission check, then the results version's. An empty `stored_digest` (kept before
/// digests were) skips the mission check.
ResumeCheck check_resumable(const std::string& what, const std::string& mission_reference,
                            const std::string& stored_digest, int stored_results_version,
                            const FileScope& files = FileScope::local());

}  // namespace sd::app
