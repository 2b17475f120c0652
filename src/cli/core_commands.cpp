// Core commands, no account needed: missions, mission show, evaluate, show-config.
#include <nlohmann/json.hpp>
#include <CLI/CLI.hpp>

#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>

#include "app/documents.hpp"
#include "app/pseudo_realities.hpp"
#include "app/evaluation_job.hpp"
#include "app/inputs.hpp"
#include "app/user_files.hpp"
#include "cli/command_registry.hpp"
#include "cli/control_software_input.hpp"
#include "cli/score_output.hpp"
#include "control/describe.hpp"
#include "evaluation/svg_frames.hpp"
#include "missions/catalogue.hpp"
#include "missions/svg.hpp"

namespace sd::cli::core_commands {

namespace {

void register_missions(CLI::App& app) {
  auto* cmd = app.add_subcommand("missions", "List the missions (name, origin, robots, duration, objective direction)");
  auto json_output = std::make_shared<bool>(false);
  cmd->add_flag("--json", *json_output, "Print one JSON document");
  cmd->footer("Example: swarmdesign missions --json");
  cmd->callback([json_output] {
    const auto missions = list_missions();
    if (*json_output) {
      std::cout << app::missions_document(missions).dump(2) << "\n";
      return;
    }
    std::printf("%-28s %-12s %6s %9s  %-9s %s\n", "NAME", "ORIGIN", "ROBOTS", "DURATION", "OBJECTIVE", "TITLE");
    for (const auto& m : missions)
      std::printf("%-28s %-12s %6d %8gs  %-9s %s\n", m.name.c_str(), m.origin.c_str(), m.robots, m.duration_s,
                  m.direction.c_str(), m.title.c_str());
  });
}

void register_mission_show(CLI::App& app) {
  auto* mission = app.add_subcommand("mission", "Describe one mission");
  mission->require_subcommand(1);
  auto* show = mission->add_subcommand("show", "Describe a mission and optionally draw its arena as SVG");
  struct Options {
    std::string name, svg;
    bool json = false;
  };
  auto o = std::make_shared<Options>();
  show->add_option("name", o->name, "Mission name or mission file")->required();
  show->add_option("--svg", o->svg, "Write a drawing of the arena to FILE");
  show->add_flag("--json", o->json, "Print one JSON document");
  show->footer("Example: swarmdesign mission show aac --svg aac.svg");
  show->callback([o] {
    const Mission m = app::load_requested_mission(o->name);
    if (!o->svg.empty()) {
      std::ofstream out(o->svg);
      if (!out) throw std::runtime_error("cannot write " + o->svg);
      out << mission_svg(m);
    }
    if (o->json) {
      std::cout << app::mission_document(m).dump(2) << "\n";
      return;
    }
    std::cout << m.title << " (" << m.name << ", " << m.origin << ")\n";
    if (!m.description.empty()) std::cout << "  " << m.description << "\n";
    std::cout << "  robots: " << m.robots << ", duration: " << m.duration_s << " s (" << m.ticks << " ticks)\n"
              << "  arena: " << m.arena.walls.size() << " walls, " << m.arena.floor_patches.size() << " floor patches, "
              << m.arena.lights.size() << " light(s)\n"
              << "  objective: " << m.objective.type << ", " << direction_name(m.objective.direction) << "\n"
              << "  source: " << m.source << "\n";
    if (!o->svg.empty()) std::cout << "  drawing written to " << o->svg << "\n";
  });
}

void register_evaluate(CLI::App& app, Context& context) {
  auto* cmd = app.add_subcommand("evaluate", "Simulate control software on a mission and print its score per seed");
  struct Options {
    // The seed is text for app::parse_seed: CLI11 would read "-1" as 2^64-1.
    std::string mission, seed = "1", seeds, trace, render, arlequin_modules, start_from, pseudo_reality, sample;
    int render_every = 10;
    int threads = 0;
    bool json = false;
    ControlSoftwareOptions software;
  };
  auto o = std::make_shared<Options>();
  cmd->add_option("--mission", o->mission, "Mission name or mission file")->required();
  auto* seed = cmd->add_option("--seed", o->seed, "Seed of the run (default 1)");
  cmd->add_option("--seeds", o->seeds, "Range of seeds A-B; also prints mean and median")->excludes(seed);
  cmd->add_option("--threads", o->threads, "Worker threads for --seeds (default: all cores)")->check(CLI::NonNegativeNumber);
  cmd->add_option("--trace", o->trace, "Write every tick's poses, LEDs and running objective to FILE (CSV)");
  auto* render = cmd->add_option("--render", o->render,
                                  "Write the run as SVG frames DIR/frame-TTTTT.svg (arena, robots, tick and objective)");
  cmd->add_option("--render-every", o->render_every, "Ticks between two --render frames (default 10: one a second)")
      ->check(CLI::PositiveNumber)
      ->needs(render);
  cmd->add_option("--arlequin-modules", o->arlequin_modules,
                  "Arlequin module set that runs modules 50-55: swarmdesign (the shipped networks, default), demiurge "
                  "(Demiurge's networks and machinery) or a folder of the six weight documents");
  cmd->add_option("--start-from", o->start_from,
                  "Start every run from the robots' poses at tick 0 of a trace FILE (ARGoS' traces, e.g. "
                  "tests/data/argos-starts/, or --trace output, uncompressed); the seed then draws only noise");
  cmd->add_option("--pseudo-reality", o->pseudo_reality,
                  "Run in a pseudo-reality sample instead of the design model: a shipped specification or a .json file");
  cmd->add_option("--sample", o->sample, "With --pseudo-reality: which sample (1, 2, ...), as assess numbers them");
  cmd->add_flag("--json", o->json, "Print one JSON document");
  add_control_software_options(*cmd, o->software);
  cmd->footer(
      "The control software ends the command line. With --pseudo-reality and --sample the runs are those\n"
      "assess scores in that sample (the same bits), and --json's robot model is the sample's.\n"
      "Example: swarmdesign evaluate --mission aac --seeds 1-20 --fsm-config --nstates 1 --s0 10 --rwm0 50\n"
      "A video from --render frames: ffmpeg -framerate 10 -pattern_type glob -i 'DIR/*.svg' run.webm");
  cmd->callback([o, &context] {
    const Mission mission = app::in_requested_sample(
        app::with_start_from(app::with_requested_arlequin_modules(app::load_requested_mission(o->mission), o->arlequin_modules),
                             o->start_from),
        o->pseudo_reality, o->sample);
    const ControlSoftware software = read_control_software(context, o->software);
    const std::vector<std::uint64_t> seeds =
        o->seeds.empty() ? std::vector<std::uint64_t>{app::parse_seed(o->seed)} : app::parse_seed_range(o->seeds);
    if (!o->trace.empty() && seeds.size() != 1) throw UsageError("--trace records one run: use it with --seed");
    if (!o->render.empty() && (seeds.size() != 1 || !o->trace.empty()))
      throw UsageError("--render draws one run: use it with --seed, without --trace");
    if (!o->render.empty()) {
      SvgFrameWriter frames(mission, o->render, o->render_every);
      print_scores(mission, software, seeds, {app::observed_run(mission, software, seeds[0], frames)}, o->json);
    } else if (!o->trace.empty())
      print_scores(mission, software, seeds, {app::traced_run(mission, software, seeds[0], o->trace)}, o->json);
    else
      score_and_print(mission, software, seeds, o->threads, o->json);
  });
}

void register_show_config(CLI::App& app, Context& context) {
  auto* cmd = app.add_subcommand("show-config", "Print control software readably, or as Graphviz DOT");
  struct Options {
    bool dot = false, canonical = false;
    ControlSoftwareOptions software;
  };
  auto o = std::make_shared<Options>();
  cmd->add_flag("--dot", o->dot, "Print Graphviz DOT");
  cmd->add_flag("--canonical", o->canonical, "Print the canonical configuration string (two-digit ids)");
  add_control_software_options(*cmd, o->software);
  cmd->footer("Example: swarmdesign show-config --dot --fsm-config --nstates 1 --s0 10 --rwm0 50 | dot -Tpng > fsm.png");
  cmd->callback([o, &context] {
    const ControlSoftware software = read_control_software(context, o->software);
    if (o->dot) std::cout << to_dot(software);
    else if (o->canonical) std::cout << to_config_string(software) << "\n";
    else std::cout << describe(software) << "  " << to_config_string(software) << "\n";
  });
}

const CommandRegistrar registrar{10, [](CLI::App& app, Context& context) {
                                   register_missions(app);
                                   register_mission_show(app);
                                   register_evaluate(app, context);
                                   register_show_config(app, context);
                                 }};

}  // namespace
}  // namespace sd::cli::core_commands
