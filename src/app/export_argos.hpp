#pragma once
// Giving SwarmDesign's work back to the AutoMoDe tool chain (export --argos, mission
// export-argos, and the --argos of status and test-design): the jobs over src/export, with
// their refusals as InvalidRequest (the request asks for what the target code base cannot read).
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/home.hpp"
#include "app/user_files.hpp"
#include "control/control_software.hpp"
#include "export/argos_experiment.hpp"
#include "export/legacy_string.hpp"
#include "missions/mission.hpp"
#include "storage/accounts.hpp"

namespace sd::app {

/// `flavour` empty: the one flavour of every module; `tree_form` "", "rootnode" or "nroot".
argos::LegacyString export_control_software(const ControlSoftware& software, const std::string& flavour = "",
                                            const std::string& tree_form = "");

/// For a report line: the export in the inferred flavour, or why there is none.
struct ArgosExportLine {
  bool exported = false;
  argos::LegacyString result;
  std::string refusal;
};
ArgosExportLine try_export_control_software(const ControlSoftware& software);
/// {"config", "flavour", "reader"} or {"refused": why}.
nlohmann::json argos_export_document(const ArgosExportLine& line);

struct MissionExportRequest {
  std::string mission;             // catalogue name or mission file
  std::filesystem::path out;       // the .argos file to write
  argos::ExperimentOptions options;
  /// A pseudo-reality sample to write instead of the design model (the same sample runs in
  /// ARGoS as here): a specification's shipped name or file, and the sample number (>= 1).
  std::string pseudo_reality{};
  std::string sample{};
};
/// Writes the file; returns what was written (its notes are for the user).
argos::Experiment export_mission(const MissionExportRequest& request);
/// The experiment file of `mission`, in sample `sample` of pseudo-reality `pseudo_reality` (read
/// under `scope`) when both are given; nothing written.
argos::Experiment mission_experiment(Mission mission, const argos::ExperimentOptions& options,
                                     const std::string& pseudo_reality = "", const std::string& sample = "",
                                     const FileScope& scope = FileScope::local());

/// A design's best (or given control software) for ARGoS3-AutoMoDe: `export-argos --design`,
/// the web's /argos and Python's argos_files.
struct ArgosFilesRequest {
  std::optional<std::string> project;       // nullopt: the active one
  std::optional<std::int64_t> design;       // nullopt: the last design with a best
  std::optional<ControlSoftware> software;  // given: on the project's mission instead
  std::string pseudo_reality{}, sample{};   // both or neither: the mission in that sample
};
/// {"design", "control_software", "argos" (the one-digit string, or why not), "file_name",
/// "experiment" (the .argos text), "notes", "loop_functions_dir", "automode_library",
/// "pseudo_reality" ({"reference", "sample"} or null), "command" (when exported)}.
nlohmann::json argos_files(Home& home, const storage::User& user, const ArgosFilesRequest& request,
                           const FileScope& scope = FileScope::local());

}  // namespace sd::app
