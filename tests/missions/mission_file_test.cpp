// Mission files: the AAC mission as specified, and every malformed-file case named.
#include <gtest/gtest.h>

#include <cmath>

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

TEST(MissionFile, EveryMalformedFieldIsNamed) {
  expect_error("{", "not valid JSON");
  expect_error(replace(kValid, "\"duration\": 10", "\"duration\": -5"), "duration: must be positive");
  expect_error(replace(kValid, "\"duration\": 10", "\"duration\": \"long\""), "duration: expected a number");
  expect_error(replace(kValid, "\"duration\": 10, ", ""), "duration: missing field");
  expect_error(replace(kValid, "\"robots\": 2", "\"robots\": 2.5"), "robots: expected an integer");
  expect_error(replace(kValid, "\"robots\": 2", "\"robots\": 500"), "robots: 500 robots do not fit");
  expect_error(replace(kValid, "robots_in_region_per_tick", "teleport"), "objective.type: unknown objective type 'teleport'");
  expect_error(replace(kValid, "\"minimize\"", "\"smaller\""), "objective.direction");
  expect_error(replace(kValid, "\"radius\": 0.3", "\"radius\": 0"), "start.circle.radius: must be positive");
  expect_error(replace(kValid, "\"radius\": 0.3", "\"radius\": 0.3, \"colour\": 1"), "start.circle.colour: unknown field");
  expect_error(replace(kValid, "\"sides\": 4", "\"sides\": 2"), "arena.walls[0].regular_polygon.sides");
  expect_error(replace(kValid, "\"name\": \"tiny\"", "\"name\": \"a/b\""), "name:");
  expect_error(replace(kValid, "\"arena\": {", "\"arena\": {\"floor\": {\"patches\": [{\"region\": {\"circle\": {\"center\": [0], \"radius\": 1}}, \"color\": \"black\"}]}, "),
               "arena.floor.patches[0].region.circle.center: expected [x, y]");
  expect_error(replace(kValid, "\"arena\": {", "\"arena\": {\"floor\": {\"background\": \"plaid\"}, "), "arena.floor.background: unknown colour");
  expect_error(replace(kValid, "\"arena\": {", "\"arena\": {\"lights\": [{\"position\": [0, 0, 1], \"intensity\": -1}], "),
               "arena.lights[0].intensity: must not be negative");
  expect_error(replace(kValid, "\"name\": \"tiny\",", "\"name\": \"tiny\", \"robot\": {\"rab_loss\": 2},"), "robot.rab_loss: must be in [0, 1]");
}

TEST(MissionFile, UnknownMissionNameIsAClearError) {
  try {
    load_mission("atlantis");
    FAIL();
  } catch (const MissionError& e) {
    EXPECT_NE(std::string(e.what()).find("unknown mission 'atlantis'"), std::string::npos);
  }
}

}  // namespace
}  // namespace sd
