// The Coconut arrest rule (AmmarHsn/loop_functions) in the unbounded grid-exploration mission.
#include <gtest/gtest.h>

#include <cmath>

#include "missions/catalogue.hpp"
#include "missions/objective.hpp"
#include "scripted_swarm.hpp"
#include "simulator/epuck.hpp"

namespace sd {
namespace {

using test::place;
using test::swarm_parked_at;

bool in_jail(Vec2 p) { return std::abs(p.x) <= 1.25 && p.y >= 1.95 && p.y <= 2.45; }

TEST(ArrestRule, RobotsThatLeaveGoToTheJailAndStayThere) {
  const Mission m = load_mission("grid-exploration-unbounded");
  ASSERT_TRUE(m.arrest.has_value());
  SwarmState s = swarm_parked_at(m.robots, {0.0, 0.0});
  for (int i = 0; i < m.robots; ++i) s.position[static_cast<std::size_t>(i)] = {-0.9 + 0.09 * i, -0.5};
  // 0: out through the opening (|p| > 1.25, y < 1.9); 1: inside (|p| = 1.2); 2: already in
  // the jail; 3: |p| = 1.25 exactly is still allowed; 4: beyond the jail's floor line y = 1.9.
  place(s, {{0.0, 1.3}, {0.0, 1.2}, {0.5, 2.2}, {0.0, 1.25}, {3.0, 1.9}});
  s.velocity[0] = {0.1, 0.0};
  Rng rng(4);
  EXPECT_EQ(apply_arrest_rule(*m.arrest, m.arena, s, rng), 1);
  EXPECT_TRUE(in_jail(s.position[0])) << s.position[0].x << ", " << s.position[0].y;
  EXPECT_EQ(s.velocity[0], (Vec2{}));
  EXPECT_NEAR(s.heading[0].x, std::cos(s.yaw[0]), 1e-12);
  EXPECT_NEAR(s.heading[0].y, std::sin(s.yaw[0]), 1e-12);
  EXPECT_EQ(s.position[1], (Vec2{0.0, 1.2}));
  EXPECT_EQ(s.position[2], (Vec2{0.5, 2.2}));
  EXPECT_EQ(s.position[3], (Vec2{0.0, 1.25}));
  EXPECT_EQ(s.position[4], (Vec2{3.0, 1.9}));
  // Jailed robots are never arrested again.
  const Vec2 jailed = s.position[0];
  EXPECT_EQ(apply_arrest_rule(*m.arrest, m.arena, s, rng), 0);
  EXPECT_EQ(s.position[0], jailed);
}

TEST(ArrestRule, JailedRobotsOverlapNeitherWallsNorEachOther) {
  const Mission m = load_mission("grid-exploration-unbounded");
  constexpr double r = epuck::kBodyRadius;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    SwarmState s = swarm_parked_at(m.robots, {});
    for (int i = 0; i < m.robots; ++i) s.position[static_cast<std::size_t>(i)] = {-1.0 + 0.1 * i, 1.5};  // all escaped
    Rng rng(seed);
    EXPECT_EQ(apply_arrest_rule(*m.arrest, m.arena, s, rng), m.robots);
    for (int i = 0; i < m.robots; ++i) {
      const Vec2 p = s.position[static_cast<std::size_t>(i)];
      EXPECT_TRUE(in_jail(p));
      for (const Wall& w : m.arena.walls) EXPECT_GE(w.distance(p, nullptr), r);
      for (int j = 0; j < i; ++j) EXPECT_GE((p - s.position[static_cast<std::size_t>(j)]).length(), 2 * r);
    }
  }
}

TEST(ArrestRule, ARobotStaysPutWhenTheJailHasNoRoom) {
  ArrestRule rule;
  rule.allowed = {Region::circle({0, 0}, 1.0), Limits{.y_min = 5.0}};
  rule.jail = Region::rectangle({0, 5.5}, {0.01, 0.01});  // a 1 cm square ...
  rule.trials = 10;
  ArenaModel arena;
  Wall wall;  // ... under a wall
  wall.center = {0, 5.5};
  wall.half_length = 0.5;
  wall.half_thickness = 0.05;
  arena.walls.push_back(wall);
  arena.compile();
  SwarmState s = swarm_parked_at(1, {2.0, 0.0});
  Rng rng(1);
  EXPECT_EQ(apply_arrest_rule(rule, arena, s, rng), 0);
  EXPECT_EQ(s.position[0], (Vec2{2.0, 0.0}));
}

TEST(ArrestRule, TheTrackerArrestsBeforeScoring) {
  const Mission m = load_mission("grid-exploration-unbounded");
  ObjectiveTracker objective(m);
  objective.reset();
  // All robots at (0.1, 1.1), |p| = 1.10, in cell (5, 9). Tick 1 sums 0, all ages become 1.
  SwarmState s = swarm_parked_at(m.robots, {0.1, 1.1});
  Rng rng(2);
  objective.post_step(s, 1, rng);
  // Tick 2: robot 0 has escaped to (1.0, 0.9), |p| = 1.35: inside the grid (cell (9, 8)) but
  // arrested first, so it visits no cell. Sum = 99 cells of age 1 (98 if it had been scored
  // before the arrest); the mission scores sum / 1000.
  s.position[0] = {1.0, 0.9};
  objective.post_step(s, 2, rng);
  EXPECT_TRUE(in_jail(s.position[0]));
  EXPECT_DOUBLE_EQ(objective.value(), 99.0 / 1000.0);
}

}  // namespace
}  // namespace sd
