#pragma once
// A design's best across the reality gap (issue #46): assessed in a pseudo-reality on the same
// seeds as in the design model (app/assess_job), the assessment document kept as
// `assessment.json` in the design's folder, so that the design's page shows its drop until it
// is assessed again. The web app assesses through here; `swarmdesign assess` prints the same
// document.
#include <nlohmann/json.hpp>

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "app/home.hpp"
#include "app/user_files.hpp"
#include "control/control_software.hpp"
#include "missions/mission.hpp"
#include "storage/accounts.hpp"

namespace sd::app {

/// At most this many simulation runs (seeds x (1 + samples)) per assessment asked for.
inline constexpr std::int64_t kMaxDesignAssessmentRuns = 20'000;

struct DesignAssessmentRequest {
  std::string pseudo_reality;   // a shipped pseudo-reality's name or a specification file (read under scope)
  std::string samples = "1-20"; // "K" or "A-B"
  std::string seeds = "1-10";
  int threads = 0;
};

/// The file a design's assessment is kept in.
std::filesystem::path design_assessment_file(const std::filesystem::path& folder);

/// Assesses `software` (labelled `label`) on `mission` and writes the document, with the
/// request as asked, atomically as folder/assessment.json; returns it. InvalidRequest naming
/// the field (spec, samples, seeds) for a bad request or more than kMaxDesignAssessmentRuns runs.
nlohmann::json assess_design_folder(const std::filesystem::path& folder, const Mission& mission,
                                    const ControlSoftware& software, const std::string& label,
                                    const DesignAssessmentRequest& request, const FileScope& scope);

/// The kept document, or nullopt when the design was never assessed.
std::optional<nlohmann::json> read_design_assessment(const std::filesystem::path& folder);

/// The same for design `design` of one of the user's projects: its best on its mission.
/// NotFound when the project or design is not the user's, or the design has no best yet.
nlohmann::json assess_project_design(Home& home, const storage::User& user, const std::string& project,
                                     std::int64_t design, const DesignAssessmentRequest& request,
                                     const FileScope& scope);
/// NotFound likewise, and when the design has no assessment.
nlohmann::json project_design_assessment(Home& home, const storage::User& user, const std::string& project,
                                         std::int64_t design);

}  // namespace sd::app
