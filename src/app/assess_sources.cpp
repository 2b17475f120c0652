#include "app/assess_sources.hpp"

#include <algorithm>
#include <utility>

#include "app/errors.hpp"
#include "app/projects.hpp"
#include "app/saved_software.hpp"
#include "control/config_string.hpp"
#include "storage/design_status.hpp"
#include "storage/design_store.hpp"
#include "storage/designs.hpp"

namespace sd::app {

void add_software_to_assess(Home& home, const std::optional<storage::User>& user, const std::optional<std::string>& project_name,
                            const AssessSources& sources, std::vector<SoftwareToAssess>& out, std::string& mission) {
  std::vector<std::pair<std::string, std::string>> folders;  // label, folder
  for (const std::string& folder : sources.design_folders) folders.emplace_back(folder, folder);
  if (!sources.saved.empty() || !sources.project_designs.empty()) {  // the user's project's
    if (!user) throw InvalidRequest("saved software and project designs are a signed-in user's");
    const storage::Project project = project_or_active(home, *user, project_name);
    if (mission.empty() && project.mission) mission = *project.mission;
    const std::vector<SavedSoftware> saved = list_saved_software(home, *user, project.name);
    for (const std::string& name : sources.saved) {
      const auto it = std::find_if(saved.begin(), saved.end(), [&](const SavedSoftware& s) { return s.name == name; });
      if (it == saved.end()) throw NotFound("--saved: project " + project.name + " has no saved software '" + name + "'");
      out.push_back({"saved " + name, parse_control_software(it->text)});
    }
    storage::Designs designs(home.workspace(), project);
    for (const std::int64_t id : sources.project_designs)
      folders.emplace_back("design " + std::to_string(id), designs.get(id).folder.string());
  }
  for (const auto& [label, folder] : folders) {
    const storage::DesignProgress progress = storage::read_design_progress(folder);
    if (!progress.best) throw InvalidRequest(label + ": the design has no result yet");
    if (mission.empty()) mission = storage::DesignStore::open(folder, true).meta().mission;
    if (!sources.elites) {
      out.push_back({label + " best", parse_control_software(progress.best->command_line)});
      continue;
    }
    for (const storage::ConfigurationScore& elite : progress.elites)
      out.push_back({label + " elite " + std::to_string(elite.id), parse_control_software(elite.command_line)});
  }
}

}  // namespace sd::app
