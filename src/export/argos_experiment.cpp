#include "export/argos_experiment.hpp"

#include <pugixml.hpp>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <set>
#include <utility>
#include <sstream>
#include <stdexcept>

#include "control/config_string.hpp"
#include "core/geometry.hpp"
#include "core/rng.hpp"
#include "simulator/epuck.hpp"
#include "simulator/placement.hpp"
#include "simulator/swarm.hpp"

namespace sd::argos {

namespace {

constexpr double kDegreesPerRadian = 180.0 / kPi;

/// Metres and degrees to the nanometre / nano-degree, shortest text: 1.066 not 1.0660254...
std::string number(double v) {
  double rounded = std::round(v * 1e9) / 1e9;
  if (rounded == 0.0) rounded = 0.0;  // no "-0"
  return format_number(rounded);
}
std::string triple(double a, double b, double c) { return number(a) + "," + number(b) + "," + number(c); }

std::string color_name(std::uint32_t rgb) {
  struct Named {
    std::uint32_t rgb;
    const char* name;
  };
  static constexpr Named kNames[] = {{0x000000, "black"}, {0xffffff, "white"},   {0x7f7f7f, "gray50"},
                                     {0xff0000, "red"},   {0x00ff00, "green"},   {0x0000ff, "blue"},
                                     {0xffff00, "yellow"}, {0xff00ff, "magenta"}, {0x00ffff, "cyan"}};
  for (const Named& n : kNames)
    if (n.rgb == rgb) return n.name;
  std::string text = std::to_string((rgb >> 16) & 0xff);
  text += ",";
  text += std::to_string((rgb >> 8) & 0xff);
  text += ",";
  text += std::to_string(rgb & 0xff);
  text += ",255";
  return text;
}

void comment(pugi::xml_node parent, const std::string& text) {
  std::string padded = " ";
  padded += text;
  padded += " ";
  parent.append_child(pugi::node_comment).set_value(padded.c_str());
}

pugi::xml_node child(pugi::xml_node parent, const char* name) { return parent.append_child(name); }

void attr(pugi::xml_node node, const char* name, const std::string& value) {
  node.append_attribute(name).set_value(value.c_str());
}

/// A child element with its attributes in order: a sensor's or actuator's declaration.
pugi::xml_node element(pugi::xml_node parent, const char* name,
                       std::initializer_list<std::pair<const char*, std::string>> attributes) {
  auto node = child(parent, name);
  for (const auto& [key, value] : attributes) attr(node, key, value);
  return node;
}

/// Walls the loop functions build themselves: TuttiFrutti's LED arena (build_arena) and the
/// walls they add after placing the robots (SCA's shelter).
std::set<std::size_t> walls_of_loop_functions(const Mission& m) {
  std::set<std::size_t> walls;
  if (!m.argos_loop_functions) return walls;
  for (const LedArena::Block& b : m.led_arena.blocks) walls.insert(b.wall);
  for (std::size_t i = 0; i < m.arena.walls.size(); ++i)
    if (m.arena.walls[i].placed_after_robots) walls.insert(i);
  return walls;
}

/// Half the side of a square arena around the origin that holds everything, plus a margin.
double arena_half_side(const Mission& m) {
  double half = 1.0;
  const auto grow = [&half](Vec2 p) { half = std::max({half, std::abs(p.x), std::abs(p.y)}); };
  for (const Wall& w : m.arena.walls) {
    const double reach = w.half_length + w.half_thickness;
    grow({std::abs(w.center.x) + reach, std::abs(w.center.y) + reach});
  }
  for (const Light& l : m.arena.lights) grow(l.position.xy());
  const auto [lo, hi] = m.start.bounds();
  grow(lo);
  grow(hi);
  return std::ceil(half + 0.5);
}

/// The start poses of a SwarmDesign run of the mission with this seed (Simulation::reset's
/// placement): off the walls and each other as the loop functions' MoveRobots draws them.
SwarmState start_poses(const Mission& m, std::uint64_t seed) {
  SwarmState swarm;
  swarm.resize(m.robots, static_cast<int>(m.arena.leds.size()));
  Rng rng(seed);
  place_robots(m.arena, [&m](Rng& r) { return m.draw_start(r); }, swarm, rng);
  return swarm;
}

void write_loop_functions(pugi::xml_node root, const Mission& m, const ExperimentOptions& options, Experiment& out) {
  if (!m.argos_loop_functions) {
    comment(root, "No loop functions: this mission file names none (its \"argos\" field). ARGoS needs loop functions "
                  "to draw the floor, place the robots and print a score.");
    out.notes.push_back("mission " + m.name + " names no ARGoS loop functions (mission-file field \"argos\"): the file "
                        "has no floor and automode_main cannot score a run; add loop functions that compute the "
                        "objective (experiments-loop-functions' CoreLoopFunctions) before using it");
    return;
  }
  const ArgosLoopFunctions& lf = *m.argos_loop_functions;
  comment(root, "Loop functions of experiments-loop-functions: they draw the floor, place the robots and compute the score.");
  auto node = child(root, "loop_functions");
  std::string library = options.loop_functions_dir;
  if (!library.empty() && library.back() != '/') library += "/";
  attr(node, "library", library + lf.library);
  attr(node, "label", lf.label);
  auto params = child(node, "params");
  attr(params, "number_robots", std::to_string(m.robots));
  for (const auto& [key, value] : lf.params) attr(params, key.c_str(), value);
}

/// Every knob of the model ARGoS cannot express (its camera's geometry, per-robot deviations)
/// that is not ARGoS' own value: left out of the file, said in it and in the notes.
void note_knobs_argos_lacks(pugi::xml_node controller, const RobotModel& r, Experiment& out) {
  const RobotModel argos_own;
  for (const RobotKnob& knob : kRobotKnobs) {
    if (knob.argos_block != ArgosBlock::None || r.*(knob.member) == argos_own.*(knob.member)) continue;
    const std::string what = std::string(knob.name) + " " + number(r.*(knob.member)) + " (ARGoS: " +
                             number(argos_own.*(knob.member)) + ")";
    comment(controller, "Not in this file: " + what + ". argos3-epuck has no attribute for it.");
    out.notes.push_back("ARGoS cannot express " + what + ": argos3-epuck has no attribute for it, so runs of this file "
                        "have ARGoS' value, not the model's");
  }
}

/// Where this model and the paired one make argos3-epuck create different random generators.
void note_generators(pugi::xml_node controller, const RobotModel& r, const RobotModel& paired, Experiment& out) {
  for (const RobotKnob& knob : kRobotKnobs) {
    if (knob.argos_generator != ArgosGenerator::IfNonZero) continue;
    const bool here = r.*(knob.member) > 0.0, there = paired.*(knob.member) > 0.0;
    if (here == there) continue;
    const std::string where = std::string(knob.argos_element) + " " + std::string(knob.argos_attribute);
    const std::string text =
        std::string(here ? "this file's " : "the paired file's ") + where + " is above 0 and the other's is 0: argos3-epuck " +
        "then creates one more random generator per robot, and ARGoS seeds generators in the order they are created, so " +
        "every later one (the loop functions' placements included) differs and runs with the same seed do not start " +
        "alike. To pair them seed by seed, give the file whose " + where + " is 0 the value 1e-9 (a generator, no noise " +
        "that matters)";
    comment(controller, "Random streams: " + text + ".");
    out.notes.push_back(text);
  }
}

void write_controller(pugi::xml_node root, const Mission& m, const ExperimentOptions& options, Experiment& out) {
  const RobotModel& r = m.robot;
  auto controllers = child(root, "controllers");
  comment(controllers, "ARGoS3-AutoMoDe's controller with the sensors, actuators and noise of the reference model; "
                       "automode_main gives it the control software from its command line (its fsm-config or "
                       "bt-config option, last).");
  auto controller = child(controllers, options.controller_tag.c_str());
  attr(controller, "id", "automode");
  attr(controller, "library", options.automode_library);
  auto actuators = child(controller, "actuators");
  element(actuators, "epuck_wheels", {{"implementation", "default"}});
  element(actuators, "epuck_rgb_leds", {{"implementation", "default"}, {"medium", "leds"}});
  element(actuators, "epuck_range_and_bearing", {{"implementation", "medium"}, {"medium", "rab"}, {"data_size", "4"}});
  auto sensors = child(controller, "sensors");
  element(sensors, "epuck_proximity", {{"implementation", "default"}, {"show_rays", "false"}, {"calibrated", "true"}});
  element(sensors, "epuck_range_and_bearing",
          {{"implementation", "medium"}, {"medium", "rab"}, {"data_size", "4"}, {"calibrated", "true"}});
  element(sensors, "epuck_light", {{"implementation", "default"}, {"show_rays", "false"}, {"calibrated", "true"}});
  element(sensors, "epuck_ground", {{"implementation", "rot_z_only"}, {"calibrated", "true"}});
  element(sensors, "epuck_omnidirectional_camera", {{"implementation", "rot_z_only"}, {"medium", "leds"}, {"show_rays", "false"}});
  // The robot model, knob by knob, where argos3-epuck reads each (kRobotKnobs' ARGoS columns).
  // RAB noise: the plugin's own spelling, noise_std_dev; IRIDIA's files say noise_std_deviation,
  // which it never reads.
  for (const RobotKnob& knob : kRobotKnobs) {
    const double value = r.*(knob.member);
    if (knob.argos_block == ArgosBlock::None || (knob.argos_block == ArgosBlock::SensorsIfNonZero && value == 0.0)) continue;
    const auto block = knob.argos_block == ArgosBlock::Actuators ? actuators : sensors;
    attr(block.child(std::string(knob.argos_element).c_str()), std::string(knob.argos_attribute).c_str(), number(value));
  }
  auto params = element(controller, "params", {{"readable", "false"}, {"history", "false"}});
  // AutoMoDeController reads its default FSM from here (fsm-config); a command-line one wins.
  if (!options.default_fsm_config.empty()) attr(params, "fsm-config", options.default_fsm_config);
  note_knobs_argos_lacks(controller, r, out);
  if (options.paired_with) note_generators(controller, r, *options.paired_with, out);
}

void write_arena(pugi::xml_node root, const Mission& m, const ExperimentOptions& options, Experiment& out) {
  const double half = arena_half_side(m);
  double top = 0.5;
  for (const Light& l : m.arena.lights) top = std::max(top, l.position.z);
  for (const Wall& w : m.arena.walls) top = std::max(top, w.height);
  const double height = std::ceil(2.0 * (top + 0.25)) / 2.0;
  auto arena = child(root, "arena");
  attr(arena, "size", triple(2 * half, 2 * half, height));
  attr(arena, "center", triple(0, 0, height / 2));

  if (m.argos_loop_functions) {
    auto floor = child(arena, "floor");
    attr(floor, "id", "floor");
    attr(floor, "source", "loop_functions");
    attr(floor, "pixels_per_meter", "300");
  }

  std::vector<Light> lights = m.arena.lights;
  if (lights.empty()) {
    comment(arena, "ARGoS needs a light when the light sensor is configured: this one is off (intensity 0).");
    lights.push_back({{0.0, 0.0, 0.4}, 0.0, 0x000000});
  }
  for (std::size_t i = 0; i < lights.size(); ++i) {
    auto light = child(arena, "light");
    // "light", the id ARGoS' own files give it (loop functions and modules that look the light
    // up find it by that name); further lights light1, light2 ...
    attr(light, "id", i == 0 ? std::string("light") : "light" + std::to_string(i));
    attr(light, "position", triple(lights[i].position.x, lights[i].position.y, lights[i].position.z));
    attr(light, "orientation", "0,0,0");
    attr(light, "color", color_name(lights[i].rgb));
    attr(light, "intensity", number(lights[i].intensity));
    attr(light, "medium", "leds");
  }

  const std::set<std::size_t> skipped = walls_of_loop_functions(m);
  if (!skipped.empty())
    comment(arena, std::to_string(skipped.size()) + " walls of the mission are built by the loop functions (the "
                   "coloured LED walls, walls added after the robots are placed) and are not repeated here.");
  for (std::size_t i = 0; i < m.arena.walls.size(); ++i) {
    if (skipped.count(i)) continue;
    const Wall& w = m.arena.walls[i];
    // <box size="x,y,z">: local y along the wall's length, then turned by the yaw.
    double yaw = std::atan2(w.axis.y, w.axis.x) * kDegreesPerRadian - 90.0;
    if (yaw <= -180.0) yaw += 360.0;
    auto box = child(arena, "box");
    attr(box, "id", "wall" + std::to_string(out.boxes));
    attr(box, "size", triple(2 * w.half_thickness, 2 * w.half_length, w.height));
    attr(box, "movable", "false");
    auto body = child(box, "body");
    attr(body, "position", triple(w.center.x, w.center.y, 0));
    attr(body, "orientation", triple(yaw, 0, 0));
    ++out.boxes;
  }
  out.walls_left_to_loop_functions = static_cast<int>(skipped.size());
  if (!m.led_arena.empty() && !m.argos_loop_functions)
    out.notes.push_back("the mission's LED walls are written as plain boxes: ARGoS shows their colours only when "
                        "loop functions build them with argos3-arena");

  comment(arena, "Unique ids epuck0 ... : AutoMoDe's controller reads a robot's id from the digits after \"epuck\".");
  const SwarmState poses = start_poses(m, options.placement_seed);
  for (std::size_t i = 0; i < poses.position.size(); ++i) {
    auto epuck = child(arena, "e-puck");
    attr(epuck, "id", "epuck" + std::to_string(i));
    auto body = child(epuck, "body");
    attr(body, "position", triple(poses.position[i].x, poses.position[i].y, 0));
    attr(body, "orientation", triple(poses.yaw[i] * kDegreesPerRadian, 0, 0));
    attr(child(epuck, "controller"), "config", "automode");
  }
}

}  // namespace

Experiment argos_experiment(const Mission& m, const ExperimentOptions& options) {
  Experiment out;
  pugi::xml_document doc;
  auto declaration = doc.append_child(pugi::node_declaration);
  attr(declaration, "version", "1.0");
  // (XML comments cannot hold a double hyphen: the options are named without theirs.)
  comment(doc, "Mission " + m.name + " (" + m.title + "), written by swarmdesign mission export-argos. Run it with "
               "automode_main -n -c FILE.argos, then the seed option and the control software (fsm-config or "
               "bt-config) last" +
               std::string(options.default_fsm_config.empty() ? "." : "; given none, it runs the FSM of the "
                                                                      "controller's params (fsm-config), the exported design."));
  auto root = child(doc, "argos-configuration");

  auto framework = child(root, "framework");
  auto experiment = child(framework, "experiment");
  attr(experiment, "length", number(m.ticks * epuck::kTickSeconds));
  attr(experiment, "ticks_per_second", number(1.0 / epuck::kTickSeconds));
  attr(experiment, "random_seed", "0");

  write_loop_functions(root, m, options, out);
  write_controller(root, m, options, out);
  write_arena(root, m, options, out);

  auto dynamics = child(child(root, "physics_engines"), "dynamics2d");
  attr(dynamics, "id", "dyn2d");
  auto media = child(root, "media");
  auto led_medium = child(media, "led");
  attr(led_medium, "id", "leds");
  attr(led_medium, "grid_size", "1,1,1");
  attr(child(media, "range_and_bearing"), "id", "rab");
  child(root, "visualization");

  std::ostringstream text;
  doc.save(text, "  ", pugi::format_default, pugi::encoding_utf8);
  out.xml = text.str();
  return out;
}

}  // namespace sd::argos
