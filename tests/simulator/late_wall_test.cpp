// Walls added after placement (ARGoS SCA's shelter): robots may start overlapping them or
// inside them, and dynamics2d then keeps the overlap until the robot drives out. Figures
// from the ARGoS trace sca_explore_seed2 (calibration traces, "SCA runs").
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "core/rng.hpp"
#include "simulator/epuck.hpp"
#include "simulator/physics.hpp"
#include "simulator/placement.hpp"
#include "simulator/robot_model.hpp"
#include "simulator/sensors.hpp"
#include "swarm_builder.hpp"
#include "test_paths.hpp"

namespace sd {
namespace {

constexpr double kR = epuck::kBodyRadius;

Wall box(Vec2 lo, Vec2 hi, bool after) {
  Wall w;
  w.center = (lo + hi) * 0.5;
  const Vec2 size = hi - lo;
  if (size.x >= size.y) {
    w.axis = {1.0, 0.0};
    w.half_length = 0.5 * size.x;
    w.half_thickness = 0.5 * size.y;
  } else {
    w.axis = {0.0, 1.0};
    w.half_length = 0.5 * size.y;
    w.half_thickness = 0.5 * size.x;
  }
  w.height = 0.2;
  w.placed_after_robots = after;
  return w;
}

/// The SCA shelter: back wall and two side walls, as the loop function adds them.
ArenaModel shelter(bool after = true) {
  ArenaModel arena;
  arena.walls.push_back(box({-0.325, -0.125}, {0.325, -0.075}, after));
  arena.walls.push_back(box({-0.3375, -0.125}, {-0.2875, 0.075}, after));
  arena.walls.push_back(box({0.2875, -0.125}, {0.3375, 0.075}, after));
  arena.lights.push_back({{0.0, 1.5, 0.4}, 2.0});
  arena.compile();
  return arena;
}

using test::one_robot;

TEST(LateWalls, InsideDistanceIsToTheNearestSide) {
  const Wall back = shelter().walls[0];
  Vec2 n;
  // Just below the middle of the back wall: the south side is nearer (Chipmunk's least
  // penetration), 0.0239 m away.
  EXPECT_NEAR(back.distance({0.0003, -0.1011}, &n), -0.0239, 1e-12);
  EXPECT_NEAR(n.y, -1.0, 1e-12);
  EXPECT_NEAR(back.distance({0.0, -0.09}, &n), -0.015, 1e-12);
  EXPECT_NEAR(n.y, 1.0, 1e-12);
  // Near an end, the end is nearer than either face.
  EXPECT_NEAR(back.distance({0.32, -0.1}, &n), -0.005, 1e-12);
  EXPECT_NEAR(n.x, 1.0, 1e-12);
  EXPECT_TRUE(back.contains({0.0, -0.1}));
  EXPECT_FALSE(back.contains({0.0, -0.07}));
}

TEST(LateWalls, PlacementIgnoresWallsAddedAfterIt) {
  // A start square entirely covered by a late wall: placement ignores it (ARGoS places
  // before the loop function adds it); the same wall placed before would make it fail.
  ArenaModel late;
  late.walls.push_back(box({-0.2, -0.2}, {0.2, 0.2}, true));
  late.compile();
  const Region start = Region::rectangle({0, 0}, {0.1, 0.1});
  Rng rng(3);
  SwarmState s;
  s.resize(3);
  place_robots(late, start, s, rng);
  for (int i = 0; i < s.size; ++i) EXPECT_TRUE(late.walls[0].contains(s.position[i]));
  ArenaModel early = late;
  early.walls[0].placed_after_robots = false;
  early.compile();
  Rng rng2(3);
  EXPECT_THROW(place_robots(early, start, s, rng2), std::runtime_error);
}

struct TraceRow {
  int tick;
  double x, y, yaw, left, right;
};

/// tests/data/traces/sca_explore_seed2_epuck4.csv: the rows of epuck4 in the ARGoS trace
/// sca_explore_seed2 (calibration traces), ticks 0-260.
std::vector<TraceRow> epuck4_trace() {
  std::ifstream in(std::string(::sd::test::source_dir()) + "/tests/data/traces/sca_explore_seed2_epuck4.csv");
  std::vector<TraceRow> rows;
  std::string line;
  std::getline(in, line);
  while (std::getline(in, line)) {
    TraceRow r{};
    if (std::sscanf(line.c_str(), "%d,%lf,%lf,%lf,%lf,%lf", &r.tick, &r.x, &r.y, &r.yaw, &r.left, &r.right) == 6) rows.push_back(r);
  }
  return rows;
}

TEST(LateWalls, ARobotStartingInsideTheBackWallMovesAsInArgos) {
  // ARGoS sca_explore_seed2: epuck4 starts with its centre inside the back wall at
  // (0.0003, -0.1011), yaw 0.266. dynamics2d stops only the approach, so for 18 ticks its y
  // stays -0.1011203 while it slides 0.2 m east; it then spins, creeps, drives west, and
  // leaves through the south face at tick ~130, overlapping the wall until tick 206. Driven
  // by the trace's wheel speeds (its yaw reset to the trace's each tick, so only contacts
  // and sliding are compared), our robot follows it within 1.5 mm all along.
  const std::vector<TraceRow> trace = epuck4_trace();
  ASSERT_EQ(trace.size(), 261u);
  const ArenaModel arena = shelter();
  SwarmState s = one_robot({trace[0].x, trace[0].y}, trace[0].yaw);
  Physics physics;
  physics.reset(1);
  double worst = 0.0;
  for (std::size_t k = 1; k < trace.size(); ++k) {
    s.wheel_left[0] = trace[k].left;
    s.wheel_right[0] = trace[k].right;
    physics.step(arena, s);
    ASSERT_TRUE(std::isfinite(s.position[0].x) && std::isfinite(s.position[0].y));
    worst = std::max(worst, (s.position[0] - Vec2{trace[k].x, trace[k].y}).length());
    if (trace[k].tick <= 19) {
      EXPECT_NEAR(s.position[0].y, trace[0].y, 1e-9) << trace[k].tick;
    }
    s.yaw[0] = trace[k].yaw;
    s.heading[0] = Vec2::polar(1.0, trace[k].yaw);
  }
  EXPECT_LT(worst, 0.0015);
}

TEST(LateWalls, RobotInsideAWallLeavesByDrivingOutAndNeverExplodes) {
  const ArenaModel arena = shelter();
  // Centre inside the back wall above its middle, heading north: it drives out into the
  // shelter at its own speed, never faster (no bias pushes bodies apart).
  SwarmState s = one_robot({0.0, -0.095}, kPi / 2);
  Physics physics;
  physics.reset(1);
  s.wheel_left[0] = s.wheel_right[0] = 0.12;
  double last = s.position[0].y;
  for (int t = 0; t < 10; ++t) {
    physics.step(arena, s);
    EXPECT_LE(s.position[0].y - last, 0.012 + 1e-12) << t;
    EXPECT_GE(s.position[0].y, last) << t;
    last = s.position[0].y;
  }
  EXPECT_GT(s.position[0].y, -0.075 + kR);  // out, in the shelter
  // Heading south from the same spot instead: the overlap may not grow, so it stays put.
  SwarmState t = one_robot({0.0, -0.095}, -kPi / 2);
  physics.reset(1);
  t.wheel_left[0] = t.wheel_right[0] = 0.12;
  for (int k = 0; k < 50; ++k) physics.step(arena, t);
  EXPECT_NEAR(t.position[0].y, -0.095, 1e-9);
  EXPECT_NEAR(t.position[0].x, 0.0, 1e-9);
}

TEST(LateWalls, ARobotInsideIsDeterministic) {
  const ArenaModel arena = shelter();
  auto run = [&] {
    SwarmState s = one_robot({-0.31, 0.0}, 2.0);
    Physics physics;
    physics.reset(1);
    for (int t = 0; t < 200; ++t) {
      s.wheel_left[0] = t % 20 < 15 ? 0.12 : -0.12;
      s.wheel_right[0] = 0.12;
      physics.step(arena, s);
    }
    return s.position[0];
  };
  const Vec2 a = run(), b = run();
  EXPECT_EQ(a.x, b.x);
  EXPECT_EQ(a.y, b.y);
  EXPECT_LT(a.length(), 1.0);
}

TEST(LateWalls, RaysStartingInsideAWallDoNotSeeIt) {
  // Chipmunk's segment query ignores a shape the ray starts in: epuck4 drives 0.2 m inside
  // the back wall before its front rays meet the side wall.
  const ArenaModel arena = shelter();
  RobotModel model;
  model.proximity_noise = 0.0;
  model.light_noise = 0.0;
  Rng rng(1);
  SwarmState s = one_robot({0.0, -0.1011}, 0.27);
  s.demand[0] = SwarmState::kDemandProximity | SwarmState::kDemandLight;
  s.broad_phase.build(s.position);
  sense_proximity(arena, model, s, rng);
  for (double v : s.proximity[0]) EXPECT_EQ(v, 0.0);
  // Near the east end, the front rays leave the back wall and meet the side wall.
  s.position[0] = {0.22, -0.1011};
  s.yaw[0] = 0.0;
  s.heading[0] = {1.0, 0.0};
  s.broad_phase.build(s.position);
  sense_proximity(arena, model, s, rng);
  EXPECT_GT(s.proximity[0][0], 0.0);
  // Inside the back wall the light is not shaded by it (it is by the same wall from behind).
  s.position[0] = {0.0, -0.1};
  sense_light(arena, model, s, rng);
  double sum = 0.0;
  for (double v : s.light[0]) sum += v;
  EXPECT_GT(sum, 0.0);
  s.position[0] = {0.0, -0.2};
  sense_light(arena, model, s, rng);
  for (double v : s.light[0]) EXPECT_EQ(v, 0.0);
}

}  // namespace
}  // namespace sd
