// mission export-argos: every catalogue mission as an ARGoS experiment file, read back with a
// real XML parser: unique e-puck ids, the duration in ticks, the mission's walls and lights,
// the robot model's noise, and the loop functions that score it.
#include <gtest/gtest.h>
#include <pugixml.hpp>

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "export/argos_experiment.hpp"
#include "missions/catalogue.hpp"
#include "simulator/robot_model.hpp"

namespace sd {
namespace {

std::vector<double> numbers(const char* text) {
  std::vector<double> values;
  std::string item;
  for (const char* c = text;; ++c) {
    if (*c == ',' || *c == '\0') {
      values.push_back(std::stod(item));
      item.clear();
      if (*c == '\0') break;
    } else {
      item += *c;
    }
  }
  return values;
}

struct Parsed {
  pugi::xml_document doc;
  pugi::xml_node root;
};

void parse(const std::string& xml, Parsed& out) {
  const pugi::xml_parse_result result = out.doc.load_string(xml.c_str());
  ASSERT_TRUE(result) << result.description() << " at " << result.offset;
  out.root = out.doc.child("argos-configuration");
  ASSERT_TRUE(out.root);
}

// The loop functions each ARGoS-scored catalogue mission must name (REGISTER_LOOP_FUNCTIONS labels).
const std::map<std::string, std::string> kLabels = {
    {"aac", "chocolate_aac_loop_functions"},      {"sca", "chocolate_sca_loop_functions"},
    {"cfa", "chocolate_cfa_loop_functions"},      {"spc", "chocolate_spc_loop_functions"},
    {"lcn", "chocolate_lcn_loop_functions"},      {"foraging", "foraging_loop_functions"},
    {"aggregation", "aggregation_loop_functions"}, {"aggregation-xor", "aggregation_xor"},
    {"tutti-aggregation", "tutti_ag_loop_function"}, {"tutti-stop", "tutti_st_loop_function"},
    {"tutti-foraging", "tutti_fr_loop_function"}, {"coconut-aggregation", "aggregation_one_spot"},
    {"coconut-foraging", "foraging_two_spots"},   {"grid-exploration", "grid_exploration"},
    {"grid-exploration-unbounded", "grid_exploration"},
};

TEST(export_ArgosExperiment, EveryCatalogueMissionIsAnArgosFileWithItsRobotsTimeWallsAndLights) {
  const auto missions = list_missions();
  ASSERT_GE(missions.size(), 15u);
  std::set<std::string> seen;
  for (const auto& summary : missions) {
    SCOPED_TRACE(summary.name);
    const Mission m = load_mission(summary.name);
    argos::ExperimentOptions options;
    options.loop_functions_dir = "/opt/elf/build";
    const argos::Experiment e = argos::argos_experiment(m, options);
    Parsed p;
    parse(e.xml, p);
    if (::testing::Test::HasFatalFailure()) return;
    EXPECT_EQ(e.xml.find("- -"), std::string::npos) << "a comment lost its double hyphen";

    // Duration: length (s) x ticks_per_second = the mission's ticks, at 10 ticks per second.
    const auto experiment = p.root.child("framework").child("experiment");
    EXPECT_EQ(experiment.attribute("ticks_per_second").as_int(), 10);
    EXPECT_EQ(std::lround(experiment.attribute("length").as_double() * 10), m.ticks);

    // E-pucks: as many as the mission's robots, ids epuck0..., unique, inside the start region.
    const auto arena = p.root.child("arena");
    std::set<std::string> ids;
    int count = 0;
    for (auto epuck : arena.children("e-puck")) {
      ids.insert(epuck.attribute("id").value());
      EXPECT_EQ(std::string(epuck.child("controller").attribute("config").value()), "automode");
      ++count;
    }
    EXPECT_EQ(count, m.robots);
    EXPECT_EQ(ids.size(), static_cast<std::size_t>(m.robots));
    EXPECT_TRUE(ids.count("epuck0"));
    EXPECT_TRUE(ids.count("epuck" + std::to_string(m.robots - 1)));
    EXPECT_EQ(m.robots, 20);

    // Walls: every wall is a box, unless the loop functions build it; boxes in the mission's order.
    int boxes = 0;
    std::size_t wall = 0;
    for (auto box : arena.children("box")) {
      while (wall < m.arena.walls.size() && m.arena.walls[wall].placed_after_robots) ++wall;
      if (!m.led_arena.empty()) {  // skip LED blocks, which the TuttiFrutti loop functions build
        std::set<std::size_t> led;
        for (const auto& b : m.led_arena.blocks) led.insert(b.wall);
        while (wall < m.arena.walls.size() && (led.count(wall) || m.arena.walls[wall].placed_after_robots)) ++wall;
      }
      ASSERT_LT(wall, m.arena.walls.size());
      const Wall& w = m.arena.walls[wall++];
      const auto size = numbers(box.attribute("size").value());
      const auto position = numbers(box.child("body").attribute("position").value());
      const auto orientation = numbers(box.child("body").attribute("orientation").value());
      ASSERT_EQ(size.size(), 3u);
      EXPECT_NEAR(size[0], 2 * w.half_thickness, 1e-8);
      EXPECT_NEAR(size[1], 2 * w.half_length, 1e-8);
      EXPECT_NEAR(size[2], w.height, 1e-8);
      EXPECT_NEAR(position[0], w.center.x, 1e-8);
      EXPECT_NEAR(position[1], w.center.y, 1e-8);
      // The box's local y axis, turned by the yaw, lies along the wall.
      const double yaw = orientation[0] * std::acos(-1.0) / 180.0;
      EXPECT_NEAR(std::abs(-std::sin(yaw) * w.axis.x + std::cos(yaw) * w.axis.y), 1.0, 1e-8);
      EXPECT_EQ(std::string(box.attribute("movable").value()), "false");
      ++boxes;
    }
    EXPECT_EQ(boxes, e.boxes);
    EXPECT_EQ(static_cast<std::size_t>(e.boxes + e.walls_left_to_loop_functions), m.arena.walls.size());

    // Lights: the mission's, in order.
    std::size_t light = 0;
    for (auto l : arena.children("light")) {
      ASSERT_LT(light, m.arena.lights.size());
      const auto position = numbers(l.attribute("position").value());
      EXPECT_NEAR(position[0], m.arena.lights[light].position.x, 1e-8);
      EXPECT_NEAR(position[1], m.arena.lights[light].position.y, 1e-8);
      EXPECT_NEAR(position[2], m.arena.lights[light].position.z, 1e-8);
      EXPECT_NEAR(l.attribute("intensity").as_double(), m.arena.lights[light].intensity, 1e-12);
      ++light;
    }
    EXPECT_EQ(light, m.arena.lights.size());

    // The controller: the robot model's noise and RAB range.
    const auto controller = p.root.child("controllers").child("automode_controller");
    ASSERT_TRUE(controller);
    const auto actuators = controller.child("actuators");
    EXPECT_DOUBLE_EQ(actuators.child("epuck_wheels").attribute("noise_std_dev").as_double(), m.robot.wheel_noise);
    EXPECT_DOUBLE_EQ(actuators.child("epuck_range_and_bearing").attribute("range").as_double(), m.robot.rab_range);
    const auto sensors = controller.child("sensors");
    EXPECT_DOUBLE_EQ(sensors.child("epuck_proximity").attribute("noise_level").as_double(), m.robot.proximity_noise);
    EXPECT_DOUBLE_EQ(sensors.child("epuck_light").attribute("noise_level").as_double(), m.robot.light_noise);
    EXPECT_DOUBLE_EQ(sensors.child("epuck_ground").attribute("noise_level").as_double(), m.robot.ground_noise);
    EXPECT_DOUBLE_EQ(sensors.child("epuck_range_and_bearing").attribute("loss_probability").as_double(), m.robot.rab_loss);
    EXPECT_TRUE(sensors.child("epuck_omnidirectional_camera"));

    // The loop functions that score it, with the mission's robots.
    const auto loop = p.root.child("loop_functions");
    const auto expected = kLabels.find(m.name);
    ASSERT_NE(expected, kLabels.end()) << "a catalogue mission without known loop functions";
    EXPECT_EQ(std::string(loop.attribute("label").value()), expected->second);
    const std::string library = loop.attribute("library").value();
    EXPECT_EQ(library.rfind("/opt/elf/build/loop-functions/", 0), 0u) << library;
    EXPECT_EQ(library.substr(library.size() - 3), ".so");
    EXPECT_EQ(loop.child("params").attribute("number_robots").as_int(), m.robots);
    EXPECT_TRUE(arena.child("floor"));
    EXPECT_TRUE(e.notes.empty());
    seen.insert(m.name);
  }
  for (const auto& [name, label] : kLabels) EXPECT_TRUE(seen.count(name)) << name;
}

// The reality gap's second step: a pseudo-reality sample runs in ARGoS as here. Every knob
// kRobotKnobs says ARGoS reads is written where it says (block, element, attribute), each with
// its own value; a noise left at zero is left out where the plugin adds it only when asked.
TEST(export_ArgosExperiment, EveryKnobArgosReadsIsWrittenWhereTheKnobTableSays) {
  Mission m = load_mission("aac");
  for (std::size_t i = 0; i < kRobotKnobs.size(); ++i)
    m.robot.*(kRobotKnobs[i].member) = kRobotKnobs[i].domain == KnobDomain::Positive ? 0.5 + 0.01 * static_cast<double>(i)
                                                                                      : 0.01 * static_cast<double>(i + 1);
  Parsed p;
  parse(argos::argos_experiment(m).xml, p);
  const auto controller = p.root.child("controllers").child("automode_controller");
  int written = 0;
  for (const RobotKnob& knob : kRobotKnobs) {
    SCOPED_TRACE(std::string(knob.name));
    if (knob.argos_block == ArgosBlock::None) continue;
    const auto block = controller.child(knob.argos_block == ArgosBlock::Actuators ? "actuators" : "sensors");
    const auto attribute = block.child(std::string(knob.argos_element).c_str()).attribute(std::string(knob.argos_attribute).c_str());
    ASSERT_TRUE(attribute) << knob.argos_element << "/" << knob.argos_attribute;
    EXPECT_DOUBLE_EQ(attribute.as_double(), m.robot.*(knob.member));
    ++written;
  }
  EXPECT_EQ(written, 8);

  m.robot.rab_noise = 0.0;
  m.robot.camera_noise = 0.0;
  Parsed quiet;
  parse(argos::argos_experiment(m).xml, quiet);
  const auto sensors = quiet.root.child("controllers").child("automode_controller").child("sensors");
  EXPECT_FALSE(sensors.child("epuck_range_and_bearing").attribute("noise_std_dev"));
  EXPECT_FALSE(sensors.child("epuck_omnidirectional_camera").attribute("noise_std_dev"));
}

/// Whether some note (or comment) holds `text`.
bool mentions(const std::vector<std::string>& notes, const std::string& text) {
  for (const std::string& n : notes)
    if (n.find(text) != std::string::npos) return true;
  return false;
}

// Issue #55's trip-wires, as a user taking a sample to ARGoS meets them.
TEST(export_ArgosExperiment, ASampleThatMakesArgosCreateAnotherRandomGeneratorSaysSoAndHowToPairIt) {
  const Mission design = load_mission("tutti-aggregation");
  ASSERT_EQ(design.robot.camera_noise, 0.0);
  Mission sample = design;
  sample.robot.camera_noise = 0.02;  // tuttifrutti-transfer's camera noise
  argos::ExperimentOptions paired;
  paired.paired_with = &design.robot;
  const argos::Experiment e = argos::argos_experiment(sample, paired);
  ASSERT_TRUE(mentions(e.notes, "epuck_omnidirectional_camera noise_std_dev is above 0 and the other's is 0")) << e.notes.size();
  EXPECT_TRUE(mentions(e.notes, "the value 1e-9"));
  EXPECT_NE(e.xml.find("Random streams: this file's epuck_omnidirectional_camera noise_std_dev"), std::string::npos);
  // Wheels, proximity, light and ground noise at 0 where the design model has them: the same.
  Mission quiet = design;
  quiet.robot.wheel_noise = 0.0;
  const argos::Experiment q = argos::argos_experiment(quiet, paired);
  EXPECT_TRUE(mentions(q.notes, "this file's epuck_wheels noise_std_dev") || mentions(q.notes, "the paired file's epuck_wheels"));
  // Zero where the design model is zero, above where it is above: paired, nothing to say.
  Mission alike = design;
  alike.robot.wheel_noise = 0.2;
  alike.robot.rab_noise = 0.01;  // the RAB sensor always has its generator
  EXPECT_TRUE(argos::argos_experiment(alike, paired).notes.empty());
  // Without a paired file, the design model's own file says nothing of streams.
  EXPECT_FALSE(mentions(argos::argos_experiment(sample).notes, "random generator"));
}

TEST(export_ArgosExperiment, EveryKnobArgosCannotExpressIsNotedNotDroppedSilently) {
  Mission m = load_mission("tutti-aggregation");
  EXPECT_TRUE(argos::argos_experiment(m).notes.empty());
  m.robot.camera_range = 0.5;
  m.robot.wheel_deviation = 0.1;
  const argos::Experiment e = argos::argos_experiment(m);
  EXPECT_TRUE(mentions(e.notes, "ARGoS cannot express camera_range 0.5 (ARGoS: 0.335)"));
  EXPECT_TRUE(mentions(e.notes, "ARGoS cannot express wheel_deviation 0.1 (ARGoS: 0)"));
  EXPECT_EQ(e.notes.size(), 2u);
  EXPECT_NE(e.xml.find("Not in this file: camera_range 0.5"), std::string::npos);
}

TEST(export_ArgosExperiment, TheLightHasArgosUsualIdAndAnFsmIsTheControllersDefault) {
  Mission m = load_mission("foraging");
  ASSERT_FALSE(m.arena.lights.empty());
  m.arena.lights.push_back(m.arena.lights.front());
  argos::ExperimentOptions options;
  options.default_fsm_config = "--nstates 1 --s0 0 --rwm0 50";
  Parsed p;
  parse(argos::argos_experiment(m, options).xml, p);
  const auto arena = p.root.child("arena");
  std::vector<std::string> ids;
  for (auto light = arena.child("light"); light; light = light.next_sibling("light")) ids.push_back(light.attribute("id").value());
  EXPECT_EQ(ids, (std::vector<std::string>{"light", "light1"}));
  const auto params = p.root.child("controllers").child("automode_controller").child("params");
  EXPECT_EQ(std::string(params.attribute("fsm-config").value()), "--nstates 1 --s0 0 --rwm0 50");
  Parsed plain;
  parse(argos::argos_experiment(m).xml, plain);
  EXPECT_FALSE(plain.root.child("controllers").child("automode_controller").child("params").attribute("fsm-config"));
}

TEST(export_ArgosExperiment, TuttiFruttiLoopFunctionsBuildTheLedArena) {
  const Mission m = load_mission("tutti-foraging");
  const argos::Experiment e = argos::argos_experiment(m);
  Parsed p;
  parse(e.xml, p);
  const auto params = p.root.child("loop_functions").child("params");
  EXPECT_EQ(std::string(params.attribute("build_arena").value()), "true");
  EXPECT_EQ(params.attribute("number_edges").as_int(), m.led_arena.sides);
  EXPECT_EQ(params.attribute("number_boxes_per_edge").as_int(), m.led_arena.blocks_per_side);
  EXPECT_EQ(e.boxes, 1);  // the divider "sep"
  EXPECT_EQ(e.walls_left_to_loop_functions, 24);
}

const char* kUserMission = R"({
  "name": "user-corridor", "duration": 60, "robots": 5,
  "arena": {"walls": [{"box": {"center": [0, 0.5], "size": [2, 0.02]}}, {"box": {"center": [0, -0.5], "size": [2, 0.02]}}],
            "lights": [{"position": [1, 0, 0.3], "intensity": 1.5, "color": "#102030"}]},
  "start": {"rectangle": {"center": [0, 0], "size": [1, 0.6]}},
  "objective": {"type": "robots_in_region_per_tick", "region": {"circle": {"center": [0.5, 0], "radius": 0.2}},
                "direction": "maximize"}
})";

TEST(export_ArgosExperiment, AMissionWithoutLoopFunctionsIsWrittenWithANote) {
  const Mission m = parse_mission(kUserMission, "test");
  const argos::Experiment e = argos::argos_experiment(m);
  Parsed p;
  parse(e.xml, p);
  EXPECT_FALSE(p.root.child("loop_functions"));
  EXPECT_FALSE(p.root.child("arena").child("floor"));
  ASSERT_EQ(e.notes.size(), 1u);
  EXPECT_NE(e.notes[0].find("loop functions"), std::string::npos);
  EXPECT_EQ(e.boxes, 2);
  EXPECT_EQ(std::string(p.root.child("arena").child("light").attribute("color").value()), "16,32,48,255");
  EXPECT_EQ(p.root.child("framework").child("experiment").attribute("length").as_int(), 60);
  int robots = 0;
  for (auto epuck : p.root.child("arena").children("e-puck")) {
    const auto position = numbers(epuck.child("body").attribute("position").value());
    EXPECT_LE(std::abs(position[0]), 0.5);
    EXPECT_LE(std::abs(position[1]), 0.3);
    ++robots;
  }
  EXPECT_EQ(robots, 5);
}

TEST(export_ArgosExperiment, TheArgosFieldIsCheckedAndLeftOutOfTheDigest) {
  const std::string plain = kUserMission;
  std::string with_argos = plain;
  with_argos.insert(plain.rfind('}'), R"(, "argos": {"loop_functions": {"label": "x_loop", "library": "lib/libx.so",
      "params": {"dist_radius": 1.2, "mode": "a<b", "fast": true}}})");
  const Mission a = parse_mission(plain, "a"), b = parse_mission(with_argos, "b");
  EXPECT_EQ(a.digest, b.digest);
  ASSERT_TRUE(b.argos_loop_functions);
  EXPECT_EQ(b.argos_loop_functions->label, "x_loop");
  const argos::Experiment e = argos::argos_experiment(b);
  Parsed p;
  parse(e.xml, p);
  const auto params = p.root.child("loop_functions").child("params");
  EXPECT_EQ(std::string(params.attribute("mode").value()), "a<b");  // escaped and read back
  EXPECT_EQ(std::string(params.attribute("fast").value()), "true");
  EXPECT_EQ(params.attribute("dist_radius").as_double(), 1.2);

  std::string bad = plain;
  bad.insert(plain.rfind('}'),
             R"(, "argos": {"loop_functions": {"label": "x", "library": "y", "params": {"number_robots": 3}}})");
  try {
    parse_mission(bad, "bad");
    FAIL();
  } catch (const MissionError& e2) {
    EXPECT_NE(std::string(e2.what()).find("argos.loop_functions.params.number_robots"), std::string::npos) << e2.what();
  }
  std::string typo = plain;
  typo.insert(plain.rfind('}'), R"(, "argos": {"loopfunctions": {}})");
  EXPECT_THROW(parse_mission(typo, "typo"), MissionError);
}

}  // namespace
}  // namespace sd
