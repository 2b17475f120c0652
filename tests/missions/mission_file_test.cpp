// Mission files: the AAC mission as specified, and every malformed-file case named.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "missions/catalogue.hpp"
#include "missions/mission.hpp"

namespace sd {
namespace {

TEST(MissionFile, AacIsTheChocolateMission) {
  const Mission m = load_mission("aac");
  EXPECT_EQ(m.robots, 20);
  EXPECT_EQ(m.ticks, 1200);
  EXPECT_EQ(m.objective.direction, Direction::Maximize);
  ASSERT_EQ(m.arena.walls.size(), 12u);
  for (const Wall& w : m.arena.walls) {
    EXPECT_NEAR(w.center.length(), 1.231, 1e-12);
    EXPECT_NEAR(std::abs(dot(w.axis, w.center)), 0.0, 1e-12);  // tangent to the circle
    EXPECT_NEAR(2 * w.half_length, 0.66, 1e-12);
  }
  EXPECT_EQ(m.arena.floor_gray({0, 0.6}), 0.0);
  EXPECT_EQ(m.arena.floor_gray({0.3, 0.6}), 0.0);      // on the rim: inclusive
  EXPECT_EQ(m.arena.floor_gray({0, -0.6}), 1.0);
  EXPECT_NEAR(m.arena.floor_gray({0.5, 0}), 127.0 / 255.0, 1e-12);
  ASSERT_EQ(m.arena.lights.size(), 1u);
  EXPECT_EQ(m.arena.lights[0].position, (Vec3{0, -1.5, 0.4}));
  EXPECT_EQ(m.arena.lights[0].intensity, 3.0);
}

TEST(MissionFile, CatalogueListsAac) {
  const auto missions = list_missions();
  const auto it = std::find_if(missions.begin(), missions.end(), [](const auto& s) { return s.name == "aac"; });
  ASSERT_NE(it, missions.end());
  EXPECT_EQ(it->direction, "maximize");
  EXPECT_TRUE(mission_exists("aac"));
  EXPECT_FALSE(mission_exists("no-such-mission"));
}

const char* kValid = R"({
  "name": "tiny", "duration": 10, "robots": 2,
  "arena": {"walls": [{"regular_polygon": {"sides": 4, "apothem": 0.5}}]},
  "start": {"circle": {"center": [0, 0], "radius": 0.3}},
  "objective": {"type": "robots_in_region_per_tick", "direction": "minimize",
                "region": {"rectangle": {"center": [0, 0], "size": [0.2, 0.2]}}}
})";

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  return text.replace(pos, from.size(), to);
}

void expect_error(const std::string& json, const std::string& needle) {
  try {
    parse_mission(json, "test");
    ADD_FAILURE() << "accepted a bad mission; expected an error mentioning '" << needle << "'";
  } catch (const MissionError& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line";
  }
}

TEST(MissionFile, AValidUserMissionLoads) {
  const Mission m = parse_mission(kValid, "test");
  EXPECT_EQ(m.ticks, 100);
  EXPECT_EQ(m.arena.walls.size(), 4u);
  EXPECT_EQ(m.objective.direction, Direction::Minimize);
}

TEST(MissionFile, TheDigestFollowsWhatTheRunsDependOnAndNothingElse) {
  const std::string digest = parse_mission(kValid, "test").digest;
  EXPECT_EQ(digest.size(), 16u);
  // Layout, comments, key order and the descriptive fields leave it alone ...
  const std::string described =
      replace(replace(kValid, "\"name\": \"tiny\",", "// a comment\n\"title\": \"Tiny\", \"description\": \"d\", \"name\":   \"tiny\","),
              "\"robots\": 2", "\"robots\":2");
  EXPECT_EQ(parse_mission(described, "elsewhere").digest, digest);
  // ... whatever changes a run changes it.
  EXPECT_NE(parse_mission(replace(kValid, "\"robots\": 2", "\"robots\": 3"), "test").digest, digest);
  EXPECT_NE(parse_mission(replace(kValid, "\"duration\": 10", "\"duration\": 11"), "test").digest, digest);
  EXPECT_NE(parse_mission(replace(kValid, "\"minimize\"", "\"maximize\""), "test").digest, digest);
  EXPECT_NE(load_mission("aac").digest, digest);
}

TEST(MissionFile, EveryMalformedFieldIsNamed) {
  expect_error("{", "not valid JSON");
  // A number no double holds is nlohmann's out_of_range, not a parse_error (fuzz_mission's kind).
  expect_error(replace(kValid, "\"duration\": 10", "\"duration\": 1e999"), "not valid JSON: number overflow parsing '1e999'");
  expect_error(replace(kValid, "\"duration\": 10", "\"duration\": -5"), "duration: must be positive");
  expect_error(replace(kValid, "\"duration\": 10", "\"duration\": \"long\""), "duration: expected a number");
  expect_error(replace(kValid, "\"duration\": 10, ", ""), "duration: missing field");
  expect_error(replace(kValid, "\"robots\": 2", "\"robots\": 2.5"), "robots: expected an integer");
  expect_error(replace(kValid, "\"robots\": 2", "\"robots\": 500"), "robots: 500 robots do not fit");
  // Found by fuzz_mission: a wall 12 km out made the compiled floor ask for terabytes.
  expect_error(replace(kValid, "\"apothem\": 0.5", "\"apothem\": 12231"), "arena.walls: reach beyond 10 m from the origin");
  expect_error(replace(kValid, "\"arena\": {", "\"arena\": {\"floor\": {\"patches\": [{\"region\": {\"circle\": {\"center\": [0, 0], \"radius\": 1e6}}, \"color\": \"black\"}]}, "),
               "arena.floor.patches[0]: reaches beyond 10 m from the origin");
  expect_error(replace(kValid, "robots_in_region_per_tick", "teleport"), "objective.type: unknown objective type 'teleport'");
  expect_error(replace(kValid, "\"minimize\"", "\"smaller\""), "objective.direction");
  expect_error(replace(kValid, "\"radius\": 0.3", "\"radius\": 0"), "start.circle.radius: must be positive");
  expect_error(replace(kValid, "\"radius\": 0.3", "\"radius\": 0.3, \"colour\": 1"), "start.circle.colour: unknown field");
  expect_error(replace(kValid, "\"sides\": 4", "\"sides\": 2"), "arena.walls[0].regular_polygon.sides");
  // 2^32 + 4 read as an int wrapped to 4 and was accepted as a square.
  expect_error(replace(kValid, "\"sides\": 4", "\"sides\": 4294967300"),
               "arena.walls[0].regular_polygon.sides: must be between -2147483648 and 2147483647");
  expect_error(replace(kValid, "\"name\": \"tiny\"", "\"name\": \"a/b\""), "name:");
  expect_error(replace(kValid, "\"arena\": {", "\"arena\": {\"floor\": {\"patches\": [{\"region\": {\"circle\": {\"center\": [0], \"radius\": 1}}, \"color\": \"black\"}]}, "),
               "arena.floor.patches[0].region.circle.center: expected [x, y]");
  expect_error(replace(kValid, "\"arena\": {", "\"arena\": {\"floor\": {\"background\": \"plaid\"}, "), "arena.floor.background: unknown colour");
  expect_error(replace(kValid, "\"arena\": {", "\"arena\": {\"lights\": [{\"position\": [0, 0, 1], \"intensity\": -1}], "),
               "arena.lights[0].intensity: must not be negative");
  expect_error(replace(kValid, "\"name\": \"tiny\",", "\"name\": \"tiny\", \"robot\": {\"rab_loss\": 2},"), "robot.rab_loss: must be in [0, 1]");
  expect_error(replace(kValid, "\"name\": \"tiny\",", "\"name\": \"tiny\", \"robot\": {\"rab_noise\": -0.1},"), "robot.rab_noise: must not be negative");
  expect_error(replace(kValid, "\"name\": \"tiny\",", "\"name\": \"tiny\", \"robot\": {\"wheel_deviation\": 1},"), "robot.wheel_deviation: must be in [0, 1)");
  expect_error(replace(kValid, "\"name\": \"tiny\",", "\"name\": \"tiny\", \"robot\": {\"camera_nois\": 0.1},"), "robot.camera_nois: unknown field");
  expect_error(replace(kValid, "\"name\": \"tiny\",", "\"name\": \"tiny\", \"robot\": [1],"), "robot: expected an object");
}

TEST(MissionFile, TheRobotSectionSetsEveryKnobOfTheRobotModel) {
  // Every knob a pseudo-reality may vary can also be a mission's own design model.
  std::string robot = "{";
  for (const RobotKnob& knob : kRobotKnobs) robot += (robot.size() > 1 ? ", \"" : "\"") + std::string(knob.name) + "\": 0.25";
  robot += "}";
  const Mission m = parse_mission(replace(kValid, "\"name\": \"tiny\",", "\"name\": \"tiny\", \"robot\": " + robot + ","), "test");
  for (const RobotKnob& knob : kRobotKnobs) EXPECT_EQ(m.robot.*(knob.member), 0.25) << knob.name;
  EXPECT_NE(m.digest, parse_mission(kValid, "test").digest);
}

TEST(MissionFile, PatchesAndStartRegionsMustBeInTheArena) {
  // The tiny arena's walls span [-0.505, 0.505]^2.
  expect_error(replace(kValid, "\"arena\": {", "\"arena\": {\"floor\": {\"patches\": [{\"region\": {\"circle\": {\"center\": [0, 0], \"radius\": 0.1}}, \"color\": \"black\"}, {\"region\": {\"circle\": {\"center\": [3, 0], \"radius\": 0.1}}, \"color\": \"black\"}]}, "),
               "arena.floor.patches[1]: lies outside the arena");
  expect_error(replace(kValid, "\"center\": [0, 0], \"radius\": 0.3", "\"center\": [5, 5], \"radius\": 0.3"),
               "start: reaches outside the walls");
  expect_error(replace(kValid, "\"radius\": 0.3", "\"radius\": 0.6"), "start: reaches outside the walls");
  // A patch reaching past the walls is fine (the foraging nest does).
  EXPECT_NO_THROW(parse_mission(replace(kValid, "\"arena\": {", "\"arena\": {\"floor\": {\"patches\": [{\"region\": {\"rectangle\": {\"center\": [0, -0.5], \"size\": [2, 0.4]}}, \"color\": \"white\"}]}, "), "test"));
}

TEST(MissionFile, WallFieldsAreChecked) {
  expect_error(replace(kValid, "\"sides\": 4", "\"sides\": 4, \"omit\": [4]"), "arena.walls[0].regular_polygon.omit[0]: must be between 0 and 3");
  expect_error(replace(kValid, "\"sides\": 4", "\"sides\": 4, \"omit\": [1, 1]"), "arena.walls[0].regular_polygon.omit[1]: side 1 is omitted twice");
  expect_error(replace(kValid, "{\"regular_polygon\": {\"sides\": 4, \"apothem\": 0.5}}",
                       "{\"regular_polygon\": {\"sides\": 4, \"apothem\": 0.5}, \"box\": {\"center\": [0, 0], \"size\": [0.1, 0.1]}}"),
               "arena.walls[0]: expected exactly one of box, regular_polygon");
  expect_error(replace(kValid, "{\"regular_polygon\"", "{\"pyramid\": 1}, {\"regular_polygon\""), "arena.walls[0].pyramid: unknown field");
}

TEST(MissionFile, WallsMayBeAddedAfterThePlacement) {
  // placed_after_robots: the walls of a box or polygon that placement does not avoid.
  const Mission plain = parse_mission(kValid, "test");
  for (const Wall& w : plain.arena.walls) EXPECT_FALSE(w.placed_after_robots);
  const Mission late = parse_mission(replace(kValid, "\"sides\": 4", "\"sides\": 4, \"placed_after_robots\": true"), "test");
  for (const Wall& w : late.arena.walls) EXPECT_TRUE(w.placed_after_robots);
  const std::string box = R"({"box": {"center": [0, 0.1], "size": [0.2, 0.05], "placed_after_robots": true}}, )";
  const Mission with_box = parse_mission(replace(kValid, "\"walls\": [", "\"walls\": [" + box), "test");
  ASSERT_EQ(with_box.arena.walls.size(), 5u);
  EXPECT_TRUE(with_box.arena.walls[0].placed_after_robots);
  EXPECT_FALSE(with_box.arena.walls[1].placed_after_robots);
  expect_error(replace(kValid, "\"sides\": 4", "\"sides\": 4, \"placed_after_robots\": 1"),
               "arena.walls[0].regular_polygon.placed_after_robots: expected true or false");
}

TEST(MissionFile, OmittedSidesLeaveTheRestOfThePolygon) {
  const Mission m = parse_mission(replace(kValid, "\"sides\": 4", "\"sides\": 4, \"omit\": [1]"), "test");
  ASSERT_EQ(m.arena.walls.size(), 3u);
  // Side 1 of a square starting at 0 degrees is the one centred at (0, 0.5): gone.
  for (const Wall& w : m.arena.walls) EXPECT_FALSE(std::abs(w.center.x) < 1e-9 && w.center.y > 0.4);
}

/// kValid with its objective replaced.
std::string with_objective(const std::string& objective) {
  const std::string valid = kValid;
  return valid.substr(0, valid.find("\"objective\":")) + "\"objective\": " + objective + "\n}";
}

TEST(MissionFile, EveryObjectiveFieldIsChecked) {
  const std::pair<std::string, std::string> cases[] = {
      {R"({"type": "robots_in_region_per_tick", "direction": "maximize", "regoin": {}})", "objective.regoin: unknown field"},
      {R"({"type": "robots_in_region_per_tick", "direction": "maximize"})", "objective.region: missing field"},
      {R"({"type": "robots_in_region_per_tick", "direction": "maximize", "region": {"circle": {"center": [0, 0], "radius": 0.1}}, "count": "sideways"})",
       "objective.count: must be \"inside\" or \"outside\""},
      {R"({"type": "robots_in_region_per_tick", "direction": "maximize", "region": {"limits": {}}})",
       "objective.region.limits: give at least one of"},
      {R"({"type": "robots_in_region_per_tick", "direction": "maximize", "region": {"limits": {"x_min": 1, "x_max": 0}}})",
       "objective.region.limits.x_max: must be greater than x_min"},
      {R"({"type": "robots_in_region_per_tick", "direction": "maximize", "region": {"ring": {"center": [0, 0], "radius": 0.3, "half_width": -1}}})",
       "objective.region.ring.half_width: must be positive"},
      {R"({"type": "robots_in_region_per_tick", "direction": "maximize", "region": {"blob": {}}})",
       "objective.region.blob: unknown zone"},
      {R"({"type": "best_region_fraction_at_end", "direction": "maximize", "regions": []})", "objective.regions: give at least one region"},
      {R"({"type": "foraging", "direction": "maximize", "nest": {"limits": {"y_max": 0}}})", "objective.sources: missing field"},
      {R"({"type": "foraging", "direction": "maximize", "sources": [{"region": {"circle": {"center": [0, 0], "radius": 0.1}}, "value": "one"}], "nest": {"limits": {"y_max": 0}}})",
       "objective.sources[0].value: expected a number"},
      {R"({"type": "grid_exploration", "direction": "minimize", "center": [0, 0], "side": 1, "cells": 0})",
       "objective.cells: must be between 1 and 1000"},
      {R"({"type": "mean_distance_to_robots", "direction": "minimize", "terms": [{"points": {"gaussian": {}}, "count": 10, "missing_distance": 1}]})",
       "objective.terms[0].points: expected one of polar_disc, on_circle, uniform_in"},
      {R"({"type": "mean_distance_to_robots", "direction": "minimize", "terms": [{"points": {"on_circle": {"center": [0, 0], "radius": 0.1}}, "count": 0, "missing_distance": 1}]})",
       "objective.terms[0].count: must be between 1 and 10000000"},
      {R"({"type": "mean_distance_to_robots", "direction": "minimize", "terms": [{"points": {"on_circle": {"center": [0, 0], "radius": 0.1}}, "count": 5, "missing_distance": 1, "robots": {"near": 1}}]})",
       "objective.terms[0].robots.near: unknown filter"},
      {R"({"type": "mean_distance_to_robots", "direction": "minimize", "terms": [{"points": {"on_circle": {"center": [0, 0], "radius": 0.1}}, "count": 5, "missing_distance": 1, "normalizer": 0}]})",
       "objective.terms[0].normalizer: must be positive"},
      {R"({"type": "largest_network_coverage", "direction": "maximize", "link_range": 0.35, "sensing_range": 0.25, "samples_per_m2": 1000})",
       "objective.clip: missing field"},
      {R"({"type": "largest_network_coverage", "direction": "maximize", "link_range": 0.35, "sensing_range": 0.25, "samples_per_m2": 1e9, "clip": {"circle": {"center": [0, 0], "radius": 1}}})",
       "objective.samples_per_m2: must be at most 10^7"},
  };
  for (const auto& [objective, needle] : cases) expect_error(with_objective(objective), needle);
}

TEST(MissionFile, ArrestRuleFieldsAreChecked) {
  const std::string ok = R"("arrest": {"allowed": [{"circle": {"center": [0, 0], "radius": 0.45}}, {"limits": {"y_min": 2}}], "jail": {"rectangle": {"center": [0, 2.2], "size": [0.5, 0.2]}}},)";
  EXPECT_NO_THROW(parse_mission(replace(kValid, "\"objective\"", ok + " \"objective\""), "test"));
  expect_error(replace(kValid, "\"objective\"", R"("arrest": {"allowed": [], "jail": {"rectangle": {"center": [0, 2.2], "size": [0.5, 0.2]}}}, "objective")"),
               "arrest.allowed: give at least one zone");
  expect_error(replace(kValid, "\"objective\"", R"("arrest": {"allowed": [{"circle": {"center": [0, 0], "radius": 0.45}}], "jail": {"rectangle": {"center": [0, 2.2], "size": [0.5, 0.2]}}}, "objective")"),
               "arrest.jail: must lie in an allowed zone");
  expect_error(replace(kValid, "\"objective\"", R"("arrest": {"allowed": [{"limits": {"y_min": 2}}], "jail": {"rectangle": {"center": [0, 2.2], "size": [0.5, 0.2]}}, "trials": 0}, "objective")"),
               "arrest.trials: must be between 1 and 100000");
}

const char* kLedMission = R"({
  "name": "leds", "duration": 10, "robots": 2,
  "arena": {"walls": [{"led_polygon": {"sides": 8, "blocks": 3, "block_length": 0.25}}]},
  "start": {"jittered_arc": {"center": [0, 0], "radius": 0.2, "jitter": 0.1}},
  "events": [{"name": "signal", "tick": {"uniform": [40, 60]}, "set_leds": [{"side": "random", "block": 2, "color": "green"}]}],
  "objective": {"type": "stop_then_move", "switch_event": "signal", "threshold": 0.0005, "direction": "minimize"}
})";

TEST(MissionFile, LedWallsEventsAndStartArcsAreChecked) {
  EXPECT_NO_THROW(parse_mission(kLedMission, "test"));
  const std::string ok = kLedMission;
  expect_error(replace(ok, "\"side\": \"random\"", "\"side\": 9"), "events[0].set_leds[0].side: must be between 1 and 8");
  expect_error(replace(ok, "\"block\": 2", "\"block\": \"sometimes\""), "events[0].set_leds[0].block: expected a block number, \"every\" or \"random\"");
  expect_error(replace(ok, "[40, 60]", "[60, 40]"), "events[0].tick.uniform[1]: must be between 60 and 100");
  expect_error(replace(ok, "[40, 60]", "[40, 200]"), "events[0].tick.uniform[1]: must be between 40 and 100");
  expect_error(replace(ok, "\"color\": \"green\"", "\"color\": \"greenish\""), "events[0].set_leds[0].color: unknown colour");
  expect_error(replace(ok, "\"switch_event\": \"signal\"", "\"switch_event\": \"whistle\""), "objective.switch_event: no event is named 'whistle'");
  expect_error(replace(ok, "\"events\": [", "\"events\": [{\"name\": \"signal\", \"tick\": 1, \"set_leds\": [{\"color\": \"red\"}]}, "),
               "events[1].name: another event is named 'signal'");
  expect_error(replace(ok, "\"block_length\": 0.25}}", "\"block_length\": 0.25}}, {\"led_polygon\": {\"sides\": 4, \"blocks\": 1, \"block_length\": 0.1}}"),
               "arena.walls[1].led_polygon: a mission has at most one led_polygon");
  expect_error(replace(ok, "\"blocks\": 3", "\"blocks\": 0"), "arena.walls[0].led_polygon.blocks: must be between 1 and 64");
  expect_error(replace(ok, "\"jitter\": 0.1", "\"jitter\": 0.1, \"spin\": 2"), "start.jittered_arc.spin: unknown field");
  expect_error(replace(ok, "\"radius\": 0.2, \"jitter\": 0.1", "\"radius\": 0.9, \"jitter\": 0.1"), "start: reaches outside the walls");
  // Events need LED walls to act on.
  expect_error(replace(kValid, "\"objective\"", R"("events": [{"name": "e", "tick": 1, "set_leds": [{"color": "red"}]}], "objective")"),
               "events[0].set_leds: the arena has no LED walls");
  expect_error(replace(ok, "\"threshold\": 0.0005", "\"threshold\": 0"), "objective.threshold: must be positive");
}

TEST(MissionFile, UnknownMissionNameIsAClearError) {
  try {
    load_mission("atlantis");
    FAIL();
  } catch (const MissionError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown mission 'atlantis'"), std::string::npos);
  }
}

TEST(MissionFile, AMissionFileAnywhereRunsAndItsErrorsNameTheFile) {
  const auto dir = std::filesystem::temp_directory_path() / ("sd_mission_file_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  {
    std::ofstream(dir / "tiny.json") << kValid;
    std::ofstream(dir / "broken.json") << replace(kValid, "\"duration\": 10", "\"duration\": -1");
  }
  EXPECT_EQ(load_mission((dir / "tiny.json").string()).name, "tiny");
  try {
    load_mission((dir / "broken.json").string());
    ADD_FAILURE() << "a broken file loaded";
  } catch (const MissionError& e) {
    EXPECT_EQ(std::string(e.what()), "broken.json: duration: must be positive");
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace sd
