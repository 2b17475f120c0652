// The built-in catalogue as a whole: every mission the issue names is listed by the binary,
// evaluates with a random walk within its stated bounds, repeats per seed, places its
// robots clear of walls and of each other, and is drawn.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "control/config_string.hpp"
#include "evaluation/simulation.hpp"
#include "missions/catalogue.hpp"
#include "missions/svg.hpp"
#include "simulator/robot_model.hpp"
#include "simulator/epuck.hpp"
#include "workflow/swarmdesign_process.hpp"

namespace sd {
namespace {

/// Each mission's direction and the range its natural value must stay in (worked
/// out by hand from each objective function).
struct Expectation {
  Direction direction;
  double lo, hi;
  bool integer;
};
const std::map<std::string, Expectation>& expected_catalogue() {
  // Grid exploration: the 4 corner cells of the 10 x 10 grid lie outside the dodecagon and
  // add sum_{t=1..1200} (t - 1) / 1000 = 719.4 each at least; 100 never-visited cells add 71 940.
  // Foraging: a round trip source -> nest is at least 2 x 0.45 m at 0.12 m/s = 7.5 s, so at
  // most 16 items per robot in 120 s.
  static const std::map<std::string, Expectation> m = {
      {"aac", {Direction::Maximize, 0, 24000, true}},
      {"aggregation", {Direction::Maximize, 0, 1, false}},
      {"aggregation-xor", {Direction::Maximize, 0, 1, false}},
      {"foraging", {Direction::Maximize, 0, 320, true}},
      {"sca", {Direction::Maximize, 0, 24000, true}},
      {"cfa", {Direction::Maximize, 0, 250, false}},
      {"spc", {Direction::Minimize, 0, 20.625 + 1e-9, false}},
      {"lcn", {Direction::Maximize, 0, 3.14159265358979 * 1.2 * 1.2, false}},
      {"coconut-aggregation", {Direction::Minimize, 0, 24000, true}},
      {"coconut-foraging", {Direction::Minimize, -320, 0, true}},
      {"grid-exploration", {Direction::Minimize, 4 * 719.4, 71940, false}},
      {"grid-exploration-unbounded", {Direction::Minimize, 4 * 719.4, 71940, false}},
      // TuttiFrutti foraging: source to nest is at least 2 x 1.13 m, so 6 items per robot.
      {"tutti-aggregation", {Direction::Minimize, 0, 24000, true}},
      {"tutti-stop", {Direction::Minimize, 0, 24000, true}},
      {"tutti-foraging", {Direction::Minimize, -120, 120, true}},
  };
  return m;
}

const ControlSoftware& random_walk() {
  static const ControlSoftware software = parse_control_software("--fsm-config --nstates 1 --s0 10 --rwm0 50");
  return software;
}

TEST(Catalogue, TheBinaryListsEveryBuiltInMission) {
  const auto home = std::filesystem::temp_directory_path() / ("sd_missions_home_" + std::to_string(::getpid()));
  std::filesystem::create_directories(home);
  const test::Outcome r = test::run_swarmdesign({"missions", "--json"}, "", {{{"SWARMDESIGN_HOME", home.string()}}, {}});
  std::filesystem::remove_all(home);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto listed = nlohmann::json::parse(r.out);
  std::map<std::string, nlohmann::json> by_name;
  for (const auto& m : listed) by_name[m["name"].get<std::string>()] = m;
  for (const auto& [name, e] : expected_catalogue()) {
    ASSERT_TRUE(by_name.count(name)) << name << " is not listed";
    EXPECT_EQ(by_name[name]["direction"], std::string(direction_name(e.direction))) << name;
    EXPECT_EQ(by_name[name]["robots"], 20) << name;
    EXPECT_EQ(by_name[name]["source"], "built-in") << name;
  }
  EXPECT_EQ(by_name.size(), expected_catalogue().size()) << "a built-in mission this test does not know";
}

TEST(Catalogue, DurationsAreThoseOfSpecReadme) {
  for (const auto& [name, e] : expected_catalogue()) {
    const Mission m = load_mission(name);
    const double expected = name == "aggregation-xor" ? 180 : name == "aggregation" ? 250 : 120;
    EXPECT_EQ(m.duration_s, expected) << name;
    EXPECT_EQ(m.ticks, static_cast<int>(expected * 10)) << name;
  }
}

TEST(Catalogue, RabRangeIsTheScenarioFilesActuatorRange) {
  // argos3-epuck reads the actuator's range: 0.5 in TuttiFrutti's scenario files, 0.7 in the
  // Chocolate, Vanilla/Maple, Coconut and Arlequin ones; 0.8 only for a file that gives none.
  for (const auto& [name, e] : expected_catalogue())
    EXPECT_EQ(load_mission(name).robot.rab_range, name.rfind("tutti-", 0) == 0 ? 0.5 : 0.7) << name;
  EXPECT_EQ(RobotModel{}.rab_range, 0.8);
}

TEST(Catalogue, EveryMissionEvaluatesARandomWalkWithinItsBounds) {
  for (const auto& [name, e] : expected_catalogue()) {
    const Mission m = load_mission(name);
    EXPECT_EQ(m.objective.direction, e.direction) << name;
    Simulation simulation(m, random_walk());
    for (const std::uint64_t seed : {1u, 2u}) {
      const double score = simulation.run(seed);
      EXPECT_GE(score, e.lo) << name << " seed " << seed;
      EXPECT_LE(score, e.hi) << name << " seed " << seed;
      if (e.integer) {
        EXPECT_EQ(score, std::round(score)) << name;
      }
      EXPECT_EQ(simulation.run(seed), score) << name << ": the same seed must give the same score";
    }
  }
}

TEST(Catalogue, PlacementNeverOverlapsWallsOrRobots) {
  constexpr double r = epuck::kBodyRadius;
  for (const auto& [name, e] : expected_catalogue()) {
    const Mission m = load_mission(name);
    Simulation simulation(m, random_walk());
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      simulation.reset(seed);
      const SwarmState& s = simulation.swarm();
      for (int i = 0; i < s.size; ++i) {
        const Vec2 p = s.position[static_cast<std::size_t>(i)];
        EXPECT_TRUE(m.start.contains(p)) << name;
        for (const Wall& w : m.arena.walls)  // walls added after placement (SCA's shelter) are not avoided
          if (!w.placed_after_robots) {
            EXPECT_GE(w.distance(p, nullptr), r) << name << " robot " << i;
          }
        for (int j = 0; j < i; ++j) EXPECT_GE((p - s.position[static_cast<std::size_t>(j)]).length(), 2 * r) << name;
      }
    }
  }
}

int count(const std::string& text, const std::string& needle) {
  int n = 0;
  for (auto pos = text.find(needle); pos != std::string::npos; pos = text.find(needle, pos + 1)) ++n;
  return n;
}

TEST(Catalogue, EveryMissionIsDrawnWithItsWallsPatchesLightsAndStart) {
  for (const auto& [name, e] : expected_catalogue()) {
    const Mission m = load_mission(name);
    const std::string svg = mission_svg(m);
    EXPECT_EQ(count(svg, "class=\"wall\""), static_cast<int>(m.arena.walls.size())) << name;
    EXPECT_EQ(count(svg, "class=\"patch\""), static_cast<int>(m.arena.floor_patches.size())) << name;
    const auto lit = std::count_if(m.arena.lights.begin(), m.arena.lights.end(), [](const Light& l) { return l.intensity > 0; });
    EXPECT_EQ(count(svg, "class=\"light\""), lit) << name;
    EXPECT_EQ(count(svg, "class=\"start\""), 1) << name;
    EXPECT_EQ(count(svg, "class=\"jail\""), m.arrest ? 1 : 0) << name;
  }
  // And through the command line.
  const auto file = std::filesystem::temp_directory_path() / ("sd_sca_" + std::to_string(::getpid()) + ".svg");
  const test::Outcome r = test::run_swarmdesign({"mission", "show", "sca", "--svg", file.string()}, "", {});
  ASSERT_EQ(r.exit_code, 0) << r.err;
  std::ifstream in(file);
  std::stringstream svg;
  svg << in.rdbuf();
  std::filesystem::remove(file);
  EXPECT_EQ(count(svg.str(), "class=\"wall\""), 15);
}

}  // namespace
}  // namespace sd
