#include "app/export_argos.hpp"

#include <stdexcept>
#include <system_error>

#include "app/errors.hpp"
#include "app/inputs.hpp"
#include "app/pseudo_realities.hpp"
#include "app/user_files.hpp"
#include "core/durable_file.hpp"

namespace sd::app {

namespace {
argos::TreeForm tree_form_named(const std::string& name) {
  if (name.empty()) return argos::TreeForm::Automatic;
  if (name == "rootnode") return argos::TreeForm::RootNode;
  if (name == "nroot") return argos::TreeForm::NRoot;
  throw InvalidRequest("--tree-form: unknown form '" + name + "' (rootnode or nroot)");
}
}  // namespace

argos::LegacyString export_control_software(const ControlSoftware& software, const std::string& flavour,
                                            const std::string& tree_form) {
  try {
    argos::ExportOptions options;
    if (!flavour.empty()) options.flavour = argos::export_flavour(flavour);
    options.tree_form = tree_form_named(tree_form);
    return argos::to_legacy_string(software, options);
  } catch (const argos::ExportRefused& e) {
    throw InvalidRequest(std::string("cannot export for ARGoS: ") + e.what());
  }
}

ArgosExportLine try_export_control_software(const ControlSoftware& software) {
  ArgosExportLine line;
  try {
    line.result = argos::to_legacy_string(software);
    line.exported = true;
  } catch (const argos::ExportRefused& e) {
    line.refusal = e.what();
  }
  return line;
}

nlohmann::json argos_export_document(const ArgosExportLine& line) {
  if (!line.exported) return {{"refused", line.refusal}};
  return {{"config", line.result.text}, {"flavour", flavour_name(line.result.flavour)}, {"reader", line.result.reader}};
}

argos::Experiment export_mission(const MissionExportRequest& request) {
  if (request.out.empty()) throw InvalidRequest("--out: give the .argos file to write");
  const std::string& tag = request.options.controller_tag;
  if (tag != "automode_controller" && tag != "automode_controller_bt")
    throw InvalidRequest("--controller: automode_controller or automode_controller_bt, not '" + tag + "'");
  Mission mission = load_requested_mission(request.mission);
  if (request.pseudo_reality.empty() != request.sample.empty())
    throw InvalidRequest("--pseudo-reality and --sample go together: the specification and which of its samples");
  if (!request.pseudo_reality.empty()) {
    const std::vector<std::uint64_t> sample = parse_sample_range(request.sample);
    if (sample.size() != 1) throw InvalidRequest("--sample: one sample number, not a range");
    mission = in_pseudo_reality(mission, load_requested_pseudo_reality(request.pseudo_reality).spec, sample.front());
  }
  argos::Experiment experiment = argos::argos_experiment(mission, request.options);
  if (mission.robot.has_deviations())
    experiment.notes.push_back("this pseudo-reality's per-robot deviations (each robot's own gains) have no ARGoS "
                               "attribute: the file gives every e-puck the sample's noise, not its deviations");
  // A kill while writing leaves the old file or the new one, never half an experiment.
  try {
    replace_file_durably(request.out, experiment.xml, 0644, Umask::Applies);
  } catch (const std::system_error& e) {
    throw std::runtime_error("cannot write " + request.out.string() + ": " + e.code().message());
  }
  return experiment;
}

}  // namespace sd::app
