// Every sensor against geometry computed by hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/rng.hpp"
#include "simulator/epuck.hpp"
#include "simulator/sensors.hpp"
#include "swarm_builder.hpp"

namespace sd {
namespace {

constexpr double kDeg = kPi / 180.0;

RobotModel noiseless() {
  RobotModel m;
  m.proximity_noise = m.light_noise = m.ground_noise = 0.0;
  m.rab_loss = 0.0;
  return m;
}

Wall vertical_wall(double x, double height = 0.08) {
  Wall w;
  w.center = {x, 0.0};
  w.axis = {0.0, 1.0};
  w.half_length = 1.0;
  w.half_thickness = 0.005;
  w.height = height;
  return w;
}

using test::robots;

double quadratic_reading(double d) {
  return d > 0.05 ? 0.0 : std::clamp(298.701 * d * d - 36.8961 * d + 1.08212, 0.0, 1.0);
}

TEST(Proximity, ReadingCurveMatchesTheArgosPolynomial) {
  EXPECT_DOUBLE_EQ(epuck::proximity_reading(0.0), 1.0);
  EXPECT_NEAR(epuck::proximity_reading(0.01), 0.7430291, 1e-9);  // 298.701e-4 - 0.368961 + 1.08212
  EXPECT_NEAR(epuck::proximity_reading(0.03), 0.244, 1e-3);
  EXPECT_EQ(epuck::proximity_reading(0.049), 0.0);  // the fit crosses zero at 4.79 cm
  EXPECT_EQ(epuck::proximity_reading(0.06), 0.0);
}

TEST(Proximity, WallAheadIsSeenByTheRaysAt11AndMinus34Degrees) {
  ArenaModel arena;
  arena.walls.push_back(vertical_wall(0.08));
  arena.compile();
  SwarmState s = robots({{{0, 0}, 0.0}});
  Rng rng(1);
  sense_proximity(arena, noiseless(), s, rng);
  const double face = 0.08 - 0.005;
  auto expected = [&](double ray_deg) {
    const double c = std::cos(ray_deg * kDeg);
    return quadratic_reading((face - 0.036 * c) / c);
  };
  EXPECT_NEAR(s.proximity[0][0], expected(11.25), 1e-12);   // ray 0 at 11.25 deg
  EXPECT_NEAR(s.proximity[0][7], expected(-33.75), 1e-12);  // ray 7 at 326.25 deg
  EXPECT_GT(s.proximity[0][0], s.proximity[0][7]);
  for (int k = 1; k < 7; ++k) EXPECT_EQ(s.proximity[0][k], 0.0) << "ray " << k;
}

TEST(Proximity, AnotherRobotIsHitWhereTheRayEntersItsBody) {
  ArenaModel arena;
  arena.compile();
  // Robot 1 turns its ray 0 (at 11.25 deg) straight towards robot 0.
  SwarmState s = robots({{{0, 0}, 0.0}, {{0.1, 0.0}, kPi - 11.25 * kDeg}});
  Rng rng(1);
  sense_proximity(arena, noiseless(), s, rng);
  // Ray 0: origin 0.036 (cos, sin)(11.25 deg), direction the same; solve |o + t d - c| = r.
  const Vec2 d{std::cos(11.25 * kDeg), std::sin(11.25 * kDeg)};
  const Vec2 o = d * 0.036;
  const Vec2 oc = o - Vec2{0.1, 0.0};
  const double b = oc.x * d.x + oc.y * d.y, c = oc.x * oc.x + oc.y * oc.y - 0.035 * 0.035;
  const double t = -b - std::sqrt(b * b - c);
  EXPECT_NEAR(s.proximity[0][0], quadratic_reading(t), 1e-12);
  // Straight at the centre: the hit is 0.1 - 0.035 - 0.036 m from the sensor point.
  EXPECT_NEAR(s.proximity[1][0], quadratic_reading(0.1 - 0.035 - 0.036), 1e-12);
  // Rays fall between bodies too: at 0.1 m robot 0 spans +-20.5 deg, and robot 1's other
  // rays (56.25 deg away or more) miss it.
  for (int k = 1; k < 8; ++k) EXPECT_EQ(s.proximity[1][k], 0.0) << "ray " << k;
}

TEST(Proximity, NoiseIsUniformAndClamped) {
  ArenaModel arena;
  arena.compile();
  RobotModel model = noiseless();
  model.proximity_noise = 0.05;
  SwarmState s = robots({{{0, 0}, 0.0}});
  Rng rng(3);
  int zeros = 0, total = 0;
  double max_value = 0.0;
  for (int t = 0; t < 2000; ++t) {
    sense_proximity(arena, model, s, rng);
    for (double v : s.proximity[0]) {
      zeros += v == 0.0;
      max_value = std::max(max_value, v);
      ++total;
    }
  }
  EXPECT_NEAR(static_cast<double>(zeros) / total, 0.5, 0.02);  // negative noise clamps to 0
  EXPECT_LE(max_value, 0.05);
  EXPECT_GT(max_value, 0.049);
}

TEST(Light, ReadingsFollowExpMinusTwoDistanceWithLinearAngularFalloff) {
  ArenaModel arena;
  arena.lights.push_back({{1.0, 0.0, 0.4}, 3.0});
  arena.compile();
  SwarmState s = robots({{{0, 0}, 0.0}});
  Rng rng(1);
  sense_light(arena, noiseless(), s, rng);
  const double base = std::exp(-2.0 * std::sqrt(1.0 + 0.16) / 3.0);
  EXPECT_NEAR(s.light[0][0], base * (1.0 - 2.0 / 10.5884), 1e-12);  // sensor at pi/10.5884
  EXPECT_NEAR(s.light[0][1], base * (1.0 - 2.0 / 3.5999), 1e-12);   // at pi/3.5999
  EXPECT_EQ(s.light[0][2], 0.0);                                    // exactly 90 deg: not < pi/2
  EXPECT_EQ(s.light[0][3], 0.0);
  const double delta7 = 2.0 * kPi - kPi / 0.5247;  // sensor at 343 deg is 17 deg to the right
  EXPECT_NEAR(s.light[0][7], base * (1.0 - 2.0 * delta7 / kPi), 1e-12);
}

TEST(Light, RobotFacingAwaySeesTheLightOnItsBackSensors) {
  ArenaModel arena;
  arena.lights.push_back({{1.0, 0.0, 0.4}, 3.0});
  arena.compile();
  SwarmState s = robots({{{0, 0}, kPi}});
  Rng rng(1);
  sense_light(arena, noiseless(), s, rng);
  EXPECT_EQ(s.light[0][0], 0.0);
  EXPECT_GT(s.light[0][3], 0.0);  // 150 deg
  EXPECT_GT(s.light[0][4], 0.0);  // 210 deg
}

TEST(Light, ANearWallOccludesTheRisingRayButAFarOneDoesNot) {
  Rng rng(1);
  for (const auto& [wall_x, occluded] : {std::pair{0.05, true}, std::pair{0.9, false}}) {
    ArenaModel arena;
    arena.walls.push_back(vertical_wall(wall_x));
    arena.lights.push_back({{1.0, 0.0, 0.4}, 3.0});
    arena.compile();
    // At x = 0.045 the ray is 1.8 cm high (blocked by 8 cm); at 0.895 it is 35.8 cm high.
    SwarmState s = robots({{{0, 0}, 0.0}});
    sense_light(arena, noiseless(), s, rng);
    EXPECT_EQ(s.light[0][0] == 0.0, occluded) << "wall at " << wall_x;
  }
}

TEST(Light, ARobotOccludesOnlyWhereTheRayIsBelowItsTop) {
  Rng rng(1);
  for (const auto& [x, occluded] : {std::pair{0.1, true}, std::pair{0.5, false}}) {
    ArenaModel arena;
    arena.lights.push_back({{1.0, 0.0, 0.4}, 3.0});
    arena.compile();
    // Entry at x - 0.035: height 0.4 (x - 0.035) = 2.6 cm (< 7.6) or 18.6 cm (> 7.6).
    SwarmState s = robots({{{0, 0}, 0.0}, {{x, 0.0}, 0.0}});
    sense_light(arena, noiseless(), s, rng);
    EXPECT_EQ(s.light[0][0] == 0.0, occluded) << "robot at " << x;
  }
}

TEST(Ground, ThreeSensorsReadTheFloorUnderThem) {
  ArenaModel arena;
  arena.floor_patches.push_back({Region::circle({0.03, 0.0}, 0.004), kGrayBlack, 0});
  arena.floor_patches.push_back({Region::circle({0.03, 0.009}, 0.004), kGrayWhite, 0xffffff});
  arena.compile();
  SwarmState s = robots({{{0, 0}, 0.0}});
  Rng rng(1);
  sense_ground(arena, noiseless(), s, rng);
  EXPECT_EQ(s.ground[0][0], kGrayWhite);  // left sensor at (0.03, +0.009)
  EXPECT_EQ(s.ground[0][1], kGrayBlack);  // centre
  EXPECT_NEAR(s.ground[0][2], 127.0 / 255.0, 1e-12);  // right: GRAY50 background
}

TEST(Ground, UniformFloorCellsAgreeWithEveryPointAroundThem) {
  // Overlapping patches of each shape (first match wins): wherever the look-up answers, every
  // point within the sensors' reach must have that gray; near the edges it must decline.
  ArenaModel arena;
  arena.floor_patches.push_back({Region::circle({0.1, 0.0}, 0.3), kGrayBlack, 0});
  arena.floor_patches.push_back({Region::rectangle({-0.2, 0.1}, {0.5, 0.3}, 0.4), kGrayWhite, 0xffffff});
  arena.floor_patches.push_back({Region::polygon({{0.2, -0.5}, {0.7, -0.4}, {0.3, 0.2}, {0.45, -0.3}}), 0.25, 0x404040});
  arena.compile();
  Rng rng(7);
  int uniform = 0, declined_near_edge = 0;
  for (int n = 0; n < 4000; ++n) {
    const Vec2 p{rng.uniform(-0.5, 0.5), rng.uniform(-0.5, 0.5)};  // inside the grid
    const double gray = arena.uniform_floor_gray(p);
    if (gray < 0.0) {
      const bool near_edge = std::any_of(arena.floor_patches.begin(), arena.floor_patches.end(),
                                         [&](const FloorPatch& f) { return f.region.boundary_distance(p) < 0.061; });
      declined_near_edge += near_edge ? 1 : 0;
      EXPECT_TRUE(near_edge) << p.x << " " << p.y;
      continue;
    }
    ++uniform;
    for (int k = 0; k < 16; ++k) {
      const Vec2 q = p + Vec2::polar(ArenaModel::kUniformFloorReach * rng.uniform(), rng.uniform(-kPi, kPi));
      ASSERT_EQ(arena.floor_gray(q), gray) << p.x << " " << p.y;
    }
  }
  EXPECT_GT(uniform, 2000);  // the look-up serves most of this busy floor
  EXPECT_GT(declined_near_edge, 50);
}

TEST(Ground, SensorsLieWithinTheUniformFloorReach) {
  for (const Vec2 o : epuck::kGroundSensorOffsets) EXPECT_LT(o.length(), ArenaModel::kUniformFloorReach);
}

TEST(RangeAndBearing, RangeIsCentreDistanceInCmMinusSevenAndBearingIsRelative) {
  ArenaModel arena;
  arena.compile();
  SwarmState s = robots({{{0, 0}, 0.0}, {{0.5, 0.0}, kPi / 2}});
  Rng rng(1);
  sense_range_and_bearing(arena, noiseless(), s, rng);
  ASSERT_EQ(s.rab_count[0], 1);
  ASSERT_EQ(s.rab_count[1], 1);
  const RabPacket& to0 = s.rab[0];
  EXPECT_NEAR(to0.range_cm, 43.0, 1e-9);
  EXPECT_NEAR(to0.bearing(), 0.0, 1e-12);
  EXPECT_EQ(to0.sender, 1);
  const RabPacket& to1 = s.rab[s.rab_stride()];
  EXPECT_NEAR(to1.bearing(), kPi / 2, 1e-12);  // robot 0 lies west; robot 1 faces north
}

TEST(RangeAndBearing, BodiesOnTheLineAndDistanceBeyondRangeBlockPackets) {
  ArenaModel arena;
  arena.compile();
  Rng rng(1);
  SwarmState blocked = robots({{{0, 0}, 0.0}, {{0.5, 0.0}, 0.0}, {{0.25, 0.02}, 0.0}});
  sense_range_and_bearing(arena, noiseless(), blocked, rng);
  EXPECT_EQ(blocked.rab_count[0], 1);  // hears only the robot in the middle
  EXPECT_EQ(blocked.rab[0].sender, 2);
  SwarmState clear = robots({{{0, 0}, 0.0}, {{0.5, 0.0}, 0.0}, {{0.25, 0.05}, 0.0}});
  sense_range_and_bearing(arena, noiseless(), clear, rng);
  EXPECT_EQ(clear.rab_count[0], 2);
  SwarmState far = robots({{{0, 0}, 0.0}, {{0.81, 0.0}, 0.0}});
  sense_range_and_bearing(arena, noiseless(), far, rng);
  EXPECT_EQ(far.rab_count[0], 0);
}

TEST(RangeAndBearing, InteriorWallsBlockButTheEnclosingWallsAreSkipped) {
  ArenaModel arena;
  arena.walls.push_back(vertical_wall(0.25));
  arena.compile();
  Rng rng(1);
  SwarmState s = robots({{{0, 0}, 0.0}, {{0.5, 0.0}, 0.0}});
  sense_range_and_bearing(arena, noiseless(), s, rng);
  EXPECT_EQ(s.rab_count[0], 0);
}

TEST(RangeAndBearing, PacketLossDropsTheConfiguredFraction) {
  ArenaModel arena;
  arena.compile();
  RobotModel model = noiseless();
  model.rab_loss = 0.85;
  SwarmState s = robots({{{0, 0}, 0.0}, {{0.3, 0.0}, 0.0}});
  Rng rng(11);
  int received = 0;
  const int trials = 20000;
  for (int t = 0; t < trials; ++t) {
    sense_range_and_bearing(arena, model, s, rng);
    received += s.rab_count[0];
  }
  const double p = static_cast<double>(received) / trials;
  EXPECT_NEAR(p, 0.15, 5 * std::sqrt(0.15 * 0.85 / trials));
}

}  // namespace
}  // namespace sd
