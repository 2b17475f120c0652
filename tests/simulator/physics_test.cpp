// Kinematics and contacts of the e-puck model (as ARGoS3's dynamics2d engine moves it).
#include <gtest/gtest.h>

#include <cmath>

#include "core/rng.hpp"
#include "simulator/epuck.hpp"
#include "simulator/physics.hpp"
#include "simulator/sensors.hpp"
#include "swarm_builder.hpp"

namespace sd {
namespace {

constexpr double kR = epuck::kBodyRadius;

ArenaModel open_arena() {
  ArenaModel arena;
  arena.compile();
  return arena;
}

ArenaModel square_arena(double half) {
  ArenaModel arena;
  for (int k = 0; k < 4; ++k) {
    Wall w;
    const double phi = k * kPi / 2;
    w.center = Vec2::polar(half, phi);
    w.axis = Vec2::polar(1.0, phi + kPi / 2);
    w.half_length = half + 0.01;
    w.half_thickness = 0.005;
    arena.walls.push_back(w);
  }
  arena.compile();
  return arena;
}

using test::one_robot;

TEST(Physics, StraightLineReachesFullSpeedAfterAccelerating) {
  const ArenaModel arena = open_arena();
  SwarmState s = one_robot({0, 0}, 0.3);
  Physics physics;
  physics.reset(1);
  s.wheel_left[0] = s.wheel_right[0] = 0.12;
  physics.step(arena, s);
  // From rest the 1.5 N drive needs ~3 sub-steps to reach 0.12 m/s, and the first sub-step
  // still moves with the old velocity: 0.0375 + 0.075 + 0.1125 + 6 x 0.12 m/s over 0.01 s
  // (ARGoS traces: about 0.0097 m instead of 0.012 m).
  const double first = s.position[0].length();
  EXPECT_NEAR(first, 0.00945, 1e-12);
  for (int t = 0; t < 10; ++t) {
    const Vec2 before = s.position[0];
    physics.step(arena, s);
    EXPECT_NEAR((s.position[0] - before).length(), 0.012, 1e-12);
  }
  // The path stays on the initial heading.
  EXPECT_NEAR(std::atan2(s.position[0].y, s.position[0].x), 0.3, 1e-12);
  EXPECT_NEAR(s.yaw[0], 0.3, 1e-12);
}

TEST(Physics, SpinInPlaceTurnsAtWheelDifferenceOverAxle) {
  const ArenaModel arena = open_arena();
  SwarmState s = one_robot({0.2, -0.1}, 0.0);
  Physics physics;
  physics.reset(1);
  s.wheel_left[0] = -0.12;
  s.wheel_right[0] = 0.12;
  const double omega = 0.24 / 0.053;
  physics.step(arena, s);
  // Chipmunk moves with the previous sub-step's velocity: from rest the first of the ten
  // sub-steps does not turn (ARGoS traces: ~0.405 rad instead of 0.453 on a turn's first tick).
  EXPECT_NEAR(s.yaw[0], 0.9 * omega * 0.1, 1e-12);
  physics.step(arena, s);
  EXPECT_NEAR(s.yaw[0], 1.9 * omega * 0.1, 1e-12);
  EXPECT_NEAR(s.position[0].x, 0.2, 1e-15);
  EXPECT_NEAR(s.position[0].y, -0.1, 1e-15);
}

TEST(Physics, MotionWithinATickIsAChordAlongTheStartHeading) {
  // Left wheel stopped, right at full speed: dynamics2d moves along the heading at the
  // start of the tick while the body turns, not along an arc.
  const ArenaModel arena = open_arena();
  SwarmState s = one_robot({0, 0}, 0.0);
  Physics physics;
  physics.reset(1);
  s.velocity[0] = {0.06, 0.0};  // already at the commanded speeds
  s.angular_velocity[0] = 0.12 / 0.053;
  s.wheel_left[0] = 0.0;
  s.wheel_right[0] = 0.12;
  physics.step(arena, s);
  EXPECT_NEAR(s.position[0].x, 0.006, 1e-12);
  EXPECT_NEAR(s.position[0].y, 0.0, 1e-12);
  EXPECT_NEAR(s.yaw[0], 0.12 / 0.053 * 0.1, 1e-12);
}

TEST(Physics, RobotStopsAtAWallAndSlidesAlongIt) {
  const ArenaModel arena = square_arena(0.5);
  // Heading 45 degrees into the east wall: the normal component is removed, the tangential
  // one remains (wall friction is only 0.07).
  SwarmState s = one_robot({0.5 - 0.005 - kR - 0.02, 0.0}, kPi / 4);
  Physics physics;
  physics.reset(1);
  s.wheel_left[0] = s.wheel_right[0] = 0.12;
  for (int t = 0; t < 30; ++t) {
    s.heading[0] = Vec2::polar(1.0, kPi / 4);
    s.yaw[0] = kPi / 4;
    physics.step(arena, s);
    EXPECT_LE(s.position[0].x, 0.5 - 0.005 - kR + 1e-9) << "tick " << t;
  }
  EXPECT_GT(s.position[0].y, 0.15);  // it slid north
}

TEST(Physics, HeadOnRobotsTouchButNeverOverlap) {
  const ArenaModel arena = open_arena();
  SwarmState s;
  s.resize(2);
  s.position = {{-0.1, 0}, {0.1, 0}};
  s.yaw = {0, kPi};
  s.heading = {{1, 0}, {-1, 0}};
  Physics physics;
  physics.reset(2);
  s.wheel_left = {0.12, 0.12};
  s.wheel_right = {0.12, 0.12};
  for (int t = 0; t < 40; ++t) {
    physics.step(arena, s);
    EXPECT_GE((s.position[1] - s.position[0]).length(), 2 * kR - 1e-9);
  }
  EXPECT_NEAR((s.position[1] - s.position[0]).length(), 2 * kR, 1e-6);  // in contact
  EXPECT_NEAR(s.position[0].x + s.position[1].x, 0.0, 1e-9);           // symmetric stalemate
}

TEST(Physics, NoOverlapGrowsInALongCrowdedRandomRun) {
  const ArenaModel arena = square_arena(0.4);
  Rng rng(7);
  SwarmState s;
  const int n = 40;
  s.resize(n);
  // A grid start, 9 cm apart.
  for (int i = 0; i < n; ++i) {
    s.position[i] = {-0.3 + 0.09 * (i % 7), -0.3 + 0.09 * (i / 7)};
    s.yaw[i] = rng.uniform(-kPi, kPi);
    s.heading[i] = Vec2::polar(1.0, s.yaw[i]);
  }
  Physics physics;
  physics.reset(n);
  double worst_overlap = 0.0, worst_wall = 0.0;
  for (int t = 0; t < 3000; ++t) {
    if (t % 10 == 0)
      for (int i = 0; i < n; ++i) {
        s.wheel_left[i] = rng.uniform(-0.12, 0.14);
        s.wheel_right[i] = rng.uniform(-0.12, 0.14);
      }
    physics.step(arena, s);
    for (int i = 0; i < n; ++i) {
      for (int j = i + 1; j < n; ++j) worst_overlap = std::max(worst_overlap, 2 * kR - (s.position[j] - s.position[i]).length());
      for (const Wall& w : arena.walls) worst_wall = std::max(worst_wall, kR - w.distance(s.position[i], nullptr));
    }
  }
  // dynamics2d itself lets bodies sink ~0.3 mm; a residual of that order is allowed, growth is not.
  EXPECT_LT(worst_overlap, 5e-4) << "robots sank into each other";
  EXPECT_LT(worst_wall, 1e-6) << "a robot sank into a wall";
  for (int i = 0; i < n; ++i) {
    EXPECT_LT(std::abs(s.position[i].x), 0.4);
    EXPECT_LT(std::abs(s.position[i].y), 0.4);
  }
}

TEST(Physics, ContactsFromTheSensorsPairTableMatchAFullScan) {
  // A crowded run stepped twice: one swarm has its pair table refreshed after every step (as
  // a simulation does, so physics takes its candidates from the sensors' close pairs), the
  // other never does (physics scans every pair). Every few steps a robot is moved after the
  // refresh, as a mission's arrest rule does, which makes the table stale. The two must move
  // bit for bit alike.
  const ArenaModel arena = square_arena(0.3);
  Rng rng(11);
  const int n = 24;
  SwarmState sensed, scanned;
  sensed.resize(n);
  for (int i = 0; i < n; ++i) {
    sensed.position[i] = {-0.24 + 0.08 * (i % 6), -0.24 + 0.08 * (i / 6)};
    sensed.yaw[i] = rng.uniform(-kPi, kPi);
    sensed.heading[i] = Vec2::polar(1.0, sensed.yaw[i]);
  }
  scanned = sensed;
  Physics with_table, without_table;
  with_table.reset(n);
  without_table.reset(n);
  int stale_steps = 0;
  for (int t = 0; t < 1500; ++t) {
    if (t % 10 == 0)
      for (int i = 0; i < n; ++i) {
        sensed.wheel_left[i] = scanned.wheel_left[i] = rng.uniform(-0.12, 0.16);
        sensed.wheel_right[i] = scanned.wheel_right[i] = rng.uniform(-0.12, 0.16);
      }
    with_table.step(arena, sensed);
    without_table.step(arena, scanned);
    sensed.broad_phase.build(sensed.position);
    if (t % 7 == 3) {  // teleport a robot next to another one, after the refresh
      const int i = t % n, j = (t + 5) % n;
      sensed.position[i] = scanned.position[i] = sensed.position[j] + Vec2{2.0 * kR + 1e-4, 0.0};
      ++stale_steps;
    }
    for (int i = 0; i < n; ++i) {
      ASSERT_EQ(sensed.position[i], scanned.position[i]) << "robot " << i << " at step " << t;
      ASSERT_EQ(sensed.velocity[i], scanned.velocity[i]) << "robot " << i << " at step " << t;
    }
  }
  EXPECT_GT(stale_steps, 200);
}

}  // namespace
}  // namespace sd
