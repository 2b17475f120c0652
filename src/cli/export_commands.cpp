// Export commands: control software for ARGoS3-AutoMoDe (export --argos) and missions as
// ARGoS experiment files (mission export-argos). The work is app/export_argos.hpp's.
#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <memory>

#include "app/accounts.hpp"
#include "app/export_argos.hpp"
#include "cli/command_registry.hpp"
#include "cli/control_software_input.hpp"
#include "cli/export_display.hpp"
#include "core/durable_file.hpp"

namespace sd::cli {

void print_argos_line(const ControlSoftware& software, const std::string& indent, const std::string& what) {
  const app::ArgosExportLine line = app::try_export_control_software(software);
  const std::string head = indent + (what.empty() ? "" : what + " ") + "for ARGoS3-AutoMoDe";
  if (!line.exported) {
    std::cout << head << ": none (" << line.refusal << ")\n";
    return;
  }
  std::cout << head << " (" << flavour_name(line.result.flavour) << ", "
            << line.result.reader << "):\n"
            << indent << "  " << line.result.text << "\n";
}

}  // namespace sd::cli

namespace sd::cli::export_commands {
namespace {

struct ExportOptions {
  bool argos = false, json = false;
  std::string flavour, tree_form;
  ControlSoftwareOptions software;
};

void export_control_software(const ExportOptions& o, const Context& context) {
  if (!o.argos) throw UsageError("export: name the target with --argos (ARGoS3-AutoMoDe, the only one so far)");
  const ControlSoftware software = read_control_software(context, o.software);
  const argos::LegacyString result = app::export_control_software(software, o.flavour, o.tree_form);
  if (o.json) {
    app::ArgosExportLine line;
    line.exported = true;
    line.result = result;
    std::cout << app::argos_export_document(line).dump(2) << "\n";
    return;
  }
  std::cout << result.text << "\n";
  std::cerr << "swarmdesign: " << flavour_name(result.flavour) << ", read by " << result.reader << "\n";
}

struct MissionExportOptions {
  std::string mission, out, pseudo_reality, sample;
  bool json = false;
  argos::ExperimentOptions experiment;
};

void export_mission(const MissionExportOptions& o) {
  app::MissionExportRequest request;
  request.mission = o.mission;
  request.out = o.out;
  request.options = o.experiment;
  request.pseudo_reality = o.pseudo_reality;
  request.sample = o.sample;
  const argos::Experiment written = app::export_mission(request);
  for (const std::string& note : written.notes) std::cerr << "swarmdesign: note: " << note << "\n";
  if (o.json) {
    nlohmann::json document = {{"file", o.out},
                               {"boxes", written.boxes},
                               {"walls_left_to_loop_functions", written.walls_left_to_loop_functions},
                               {"notes", written.notes}};
    std::cout << document.dump(2) << "\n";
    return;
  }
  std::cout << "Wrote " << o.out << " (" << written.boxes << " walls as boxes";
  if (written.walls_left_to_loop_functions > 0)
    std::cout << ", " << written.walls_left_to_loop_functions << " left to the loop functions";
  std::cout << ")\nRun it with: automode_main -n -c " << o.out << " --seed 1 --fsm-config ...\n";
}

struct DesignExportOptions {
  std::string project, out, pseudo_reality, sample;
  std::int64_t design = 0;
  bool json = false;
};

void export_design(const DesignExportOptions& o) {
  app::ArgosFilesRequest request;
  if (!o.project.empty()) request.project = o.project;
  if (o.design > 0) request.design = o.design;
  request.pseudo_reality = o.pseudo_reality;
  request.sample = o.sample;
  app::Home home;
  const nlohmann::json files = app::argos_files(home, app::signed_in_user(home), request);
  const std::filesystem::path out = o.out.empty() ? files["file_name"].get<std::string>() : o.out;
  // A kill while writing leaves the old file or the new one, never half an experiment.
  replace_file_durably(out, files["experiment"].get<std::string>(), 0644, Umask::Applies);
  for (const auto& note : files["notes"]) std::cerr << "swarmdesign: note: " << note.get<std::string>() << "\n";
  if (o.json) {
    std::cout << files.dump(2) << "\n";
    return;
  }
  std::cout << "Wrote " << out.string() << ": design " << files["design"] << "'s mission"
            << (o.sample.empty() ? "" : " in sample " + o.sample + " of " + o.pseudo_reality) << "\n";
  if (files.contains("command"))
    std::cout << "Run its best with:\n  " << files["command"].get<std::string>() << "\n";
  else
    std::cout << "Its best has no ARGoS3-AutoMoDe string: " << files["argos"]["refused"].get<std::string>() << "\n";
}

const CommandRegistrar registrar{12, [](CLI::App& app, Context& context) {
  auto o = std::make_shared<ExportOptions>();
  auto* cmd = app.add_subcommand("export", "Print control software as the AutoMoDe tool chain reads it");
  cmd->add_flag("--argos", o->argos, "For ARGoS3-AutoMoDe: the one-digit string of the flavour's code base");
  cmd->add_option("--flavour", o->flavour,
                  "chocolate, tuttifrutti, maple, coconut or arlequin (default: the flavour of every module)");
  cmd->add_option("--tree-form", o->tree_form,
                  "Maple trees: rootnode (Maple's own form, the default when the tree has its shape) or nroot "
                  "(the BehaviorTree branch's)");
  cmd->add_flag("--json", o->json, "Print one JSON document: config, flavour, reader");
  add_control_software_options(*cmd, o->software);
  cmd->footer(
      "The control software ends the command line. Coconut and Arlequin have no one-digit code base: they\n"
      "export in the two-digit form of Demiurge, the only code base that has them.\n\n"
      "Example:\n  swarmdesign export --argos --fsm-config --nstates 1 --s0 10 --rwm0 50\n"
      "  swarmdesign export --argos --flavour maple --bt-config --nroot 3 --nchildroot 1 --n0 0 --nchild0 2 "
      "--n00 6 --c00 45 --p00 0.5 --n01 5 --a01 42 --p01 0");
  cmd->callback([o, &context] { export_control_software(*o, context); });

  auto m = std::make_shared<MissionExportOptions>();
  auto* mission = app.get_subcommand("mission");
  mission->description("Describe one mission, or write it as an ARGoS experiment file");
  auto* argos = mission->add_subcommand("export-argos", "Write a mission as an ARGoS experiment file for automode_main");
  argos->add_option("mission", m->mission, "Mission name or mission file")->required();
  argos->add_option("--out", m->out, "The .argos file to write")->required();
  argos->add_option("--loop-functions-dir", m->experiment.loop_functions_dir,
                    "experiments-loop-functions' build folder, put before the mission's loop-function library");
  argos->add_option("--automode-library", m->experiment.automode_library,
                    "ARGoS3-AutoMoDe's libautomode.so, for the controller");
  argos->add_option("--controller", m->experiment.controller_tag,
                    "automode_controller (default; automode_main) or automode_controller_bt (automode_main_bt's trees)");
  argos->add_option("--pseudo-reality", m->pseudo_reality,
                    "Write a pseudo-reality's noise instead of the design model's: a shipped specification or a .json file");
  argos->add_option("--sample", m->sample, "With --pseudo-reality: which sample (1, 2, ...)");
  argos->add_flag("--json", m->json, "Print one JSON document");
  argos->footer(
      "The e-pucks are epuck0 ... (unique ids for AutoMoDe's messages); the loop functions named by the\n"
      "mission file's \"argos\" field draw the floor and score each run.\n\n"
      "Example:\n  swarmdesign mission export-argos aac --out aac.argos \\\n"
      "      --loop-functions-dir ~/experiments-loop-functions/build \\\n"
      "      --automode-library ~/ARGoS3-AutoMoDe/build/src/libautomode.so\n"
      "  swarmdesign mission export-argos aac --out aac-pr3.argos --pseudo-reality sampled-around --sample 3");
  argos->callback([m] { export_mission(*m); });

  auto d = std::make_shared<DesignExportOptions>();
  auto* design = app.add_subcommand("export-argos", "Write a design's mission as an ARGoS experiment file, with the line that runs its best");
  design->add_option("--design", d->design, "This design (default: the project's last design with a best)")
      ->check(CLI::PositiveNumber);
  design->add_option("--project", d->project, "The design's project (default: the active one)");
  design->add_option("--out", d->out, "The .argos file to write (default: ./MISSION.argos)");
  design->add_option("--pseudo-reality", d->pseudo_reality,
                     "Write a pseudo-reality's noise instead of the design model's: a shipped specification or a .json file");
  design->add_option("--sample", d->sample, "With --pseudo-reality: which sample (1, 2, ...)");
  design->add_flag("--json", d->json, "Print one JSON document (the web's ARGoS files give the same)");
  design->footer(
      "The design's own mission (the one it was made for) as mission export-argos writes it, and the\n"
      "automode_main command line that runs the design's best in it; an FSM best is also the file's default\n"
      "(automode_main runs it when given none). With --pseudo-reality and --sample, the same sample of\n"
      "robot model the simulator runs (the reality gap's second step, in ARGoS); the terminal and the file\n"
      "say where ARGoS' random streams would not pair it with the design model's file, and which knobs\n"
      "ARGoS cannot express.\n\n"
      "Example:\n  swarmdesign export-argos --design 2 --out aac.argos\n"
      "  swarmdesign export-argos --pseudo-reality sampled-around --sample 3 --json");
  design->callback([d] { export_design(*d); });
}};

}  // namespace
}  // namespace sd::cli::export_commands
