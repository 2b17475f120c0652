#include "app/export_argos.hpp"

#include <stdexcept>
#include <system_error>

#include "app/errors.hpp"
#include "app/inputs.hpp"
#include "app/pseudo_realities.hpp"
#include "app/test_design.hpp"
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

argos::Experiment mission_experiment(Mission mission, const argos::ExperimentOptions& options,
                                     const std::string& pseudo_reality, const std::string& sample, const FileScope& scope) {
  const std::string& tag = options.controller_tag;
  if (tag != "automode_controller" && tag != "automode_controller_bt")
    throw InvalidRequest("--controller: automode_controller or automode_controller_bt, not '" + tag + "'");
  // A sample's file is run against the design model's: the exporter says where ARGoS' random
  // streams would not pair them (and every knob ARGoS cannot express).
  const RobotModel design_model = mission.robot;
  mission = in_requested_sample(std::move(mission), pseudo_reality, sample, scope);
  argos::ExperimentOptions sample_options = options;
  if (!pseudo_reality.empty()) sample_options.paired_with = &design_model;
  return argos::argos_experiment(mission, sample_options);
}

argos::Experiment export_mission(const MissionExportRequest& request) {
  if (request.out.empty()) throw InvalidRequest("--out: give the .argos file to write");
  argos::Experiment experiment = mission_experiment(load_requested_mission(request.mission), request.options,
                                                    request.pseudo_reality, request.sample);
  // A kill while writing leaves the old file or the new one, never half an experiment.
  try {
    replace_file_durably(request.out, experiment.xml, 0644, Umask::Applies);
  } catch (const std::system_error& e) {
    throw std::runtime_error("cannot write " + request.out.string() + ": " + e.code().message());
  }
  return experiment;
}

nlohmann::json argos_files(Home& home, const storage::User& user, const ArgosFilesRequest& request, const FileScope& scope) {
  const TestTarget target = test_target(home, user, request.project, request.software, request.design, scope);
  const ArgosExportLine line = try_export_control_software(target.software);
  argos::ExperimentOptions options;
  if (target.software.architecture == Architecture::BehaviourTree) options.controller_tag = "automode_controller_bt";
  // An FSM is also the file's default: automode_main runs it when given no control software.
  else if (line.exported) {
    // As IRIDIA's files write it: the states, without the command line's option name.
    const std::string prefix = "--fsm-config ";
    const std::string& text = line.result.text;
    options.default_fsm_config = text.starts_with(prefix) ? text.substr(prefix.size()) : text;
  }
  const argos::Experiment experiment = mission_experiment(target.mission, options, request.pseudo_reality, request.sample, scope);
  const std::string file = target.mission.name + ".argos";
  nlohmann::json doc = {{"design", target.design_id ? nlohmann::json(*target.design_id) : nlohmann::json()},
                        {"control_software", target.configuration},
                        {"argos", argos_export_document(line)},
                        {"file_name", file},
                        {"experiment", experiment.xml},
                        {"notes", experiment.notes},
                        {"loop_functions_dir", options.loop_functions_dir},
                        {"automode_library", options.automode_library},
                        {"pseudo_reality", request.pseudo_reality.empty() ? nlohmann::json()
                                               : nlohmann::json{{"reference", request.pseudo_reality}, {"sample", request.sample}}}};
  // As the file's own comment says: no visualisation, a seed, the control software last.
  if (line.exported) {
    const bool bt = line.result.reader.find("automode_main_bt") != std::string::npos;
    doc["command"] = std::string(bt ? "automode_main_bt" : "automode_main") + " -n -c " + file + " --seed 1 " + line.result.text;
  }
  return doc;
}

}  // namespace sd::app
