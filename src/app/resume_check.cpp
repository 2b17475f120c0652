#include "app/resume_check.hpp"

#include "app/errors.hpp"
#include "evaluation/results_version.hpp"

namespace sd::app {

std::string results_version_refusal(const std::string& what, int stored_results_version, int robots) {
  if (scores_as_this_build(stored_results_version, robots)) return "";
  return what + " was run by a swarmdesign whose simulations score differently (results version " +
         std::to_string(stored_results_version) + ", this one " + std::to_string(kResultsVersion) +
         "), and resuming would mix runs of two simulators; finish it with that version, or start anew";
}

ResumeCheck check_resumable(const std::string& what, const std::string& mission_reference,
                            const std::string& stored_digest, int stored_results_version,
                            const FileScope& files) {
  ResumeCheck check;
  try {
    check.mission = load_requested_mission(mission_reference, files);
  } catch (const std::exception& e) {  // the mission's own error, or the file rule's refusal
    check.refusal = "the mission of " + what + " cannot be loaded: " + e.what();
    return check;
  }
  if (!stored_digest.empty() && stored_digest != check.mission.digest)
    check.refusal = "the mission " + mission_reference + " has changed since " + what +
                    " started, and resuming would mix runs of two missions; restore it, or start anew";
  else
    check.refusal = results_version_refusal(what, stored_results_version, check.mission.robots);
  return check;
}

}  // namespace sd::app
