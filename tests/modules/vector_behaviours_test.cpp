// Stop, Phototaxis, Anti-phototaxis, Attraction, Repulsion (ARGoS3-AutoMoDe master):
// each computes a vector from the reference model, replaces vectors shorter than 0.1 by
// "straight ahead" and drives with W(v). Expected vectors are computed here by hand.
#include <gtest/gtest.h>

#include "module_test_helpers.hpp"

namespace sd {
namespace {

using test::expect_wheels;
using test::kFull;
using test::module;
using test::spec_wheels;

Actuation run(const ModuleInstance& behaviour, const ReferenceModel& rm) {
  BehaviourMemory memory;
  Rng rng(0);
  return run_behaviour(behaviour, memory, rm, rng);
}

ReferenceModel model(Vec2 light, Vec2 proximity, Vec2 attraction_sum = {}) {
  ReferenceModel rm;
  rm.light = light;
  rm.proximity = proximity;
  rm.rab_steps[0] = attraction_sum;  // one buffered step holds the whole sum
  return rm;
}

const Actuation kStraight{kFull, kFull, 0};

TEST(ModulesStop, AlwaysStops) {
  const Actuation a = run(module(11), model(Vec2::polar(1, 1.0), Vec2::polar(1, 0.0), {0.3, 0.3}));
  EXPECT_EQ(a.left_cm, 0.0);
  EXPECT_EQ(a.right_cm, 0.0);
}

/// Unit vector at `deg` degrees; exact on the axes (polar(1, pi) has y = 1.2e-16, whose
/// turn direction is a rounding accident, see ModulesWheelsTowards.StraightBehindSpinsRightInPlace).
Vec2 unit_degrees(int deg) {
  if (deg == 180 || deg == -180) return {-1.0, 0.0};
  if (deg == 0) return {1.0, 0.0};
  return Vec2::polar(1.0, degrees_to_radians(deg));
}

TEST(ModulesPhototaxis, HeadsTowardsTheLight) {
  for (int deg = -170; deg <= 180; deg += 10) {
    const Vec2 light = unit_degrees(deg);
    SCOPED_TRACE(deg);
    expect_wheels(run(module(12), model(light, {})), spec_wheels(light));
  }
}

TEST(ModulesPhototaxis, ObstacleTermIsFiveTimesTheProximityVector) {
  const Vec2 light{1.0, 0.0};
  const Vec2 obstacle = Vec2::polar(0.3, degrees_to_radians(20));
  const Vec2 v{1.0 - 1.5 * std::cos(degrees_to_radians(20)), -1.5 * std::sin(degrees_to_radians(20))};
  const Actuation a = run(module(12), model(light, obstacle));
  expect_wheels(a, spec_wheels(v));
  EXPECT_EQ(a.left_cm, kFull);  // obstacle front-left pushes to the right
  EXPECT_LT(a.right_cm, 0.0);
}

TEST(ModulesPhototaxis, NoLightNoObstacleGoesStraight) { expect_wheels(run(module(12), model({}, {})), kStraight); }

TEST(ModulesPhototaxis, ShortVectorFallsBackToStraight) {
  // v = -5 * (0.01, 0) = (-0.05, 0): shorter than 0.1, so straight rather than a spin.
  expect_wheels(run(module(12), model({}, {0.01, 0.0})), kStraight);
  // Light and obstacle cancel exactly: straight, not stop.
  expect_wheels(run(module(12), model({1.0, 0.0}, {0.2, 0.0})), kStraight);
  // Just above the threshold the vector is followed: (-0.11, 0) spins right.
  expect_wheels(run(module(12), model({}, {0.022, 0.0})), {kFull, -kFull, 0});
}

TEST(ModulesAntiPhototaxis, HeadsAwayFromTheLight) {
  for (int deg = -170; deg <= 180; deg += 10) {
    const Vec2 light = unit_degrees(deg);
    SCOPED_TRACE(deg);
    expect_wheels(run(module(13), model(light, {})), spec_wheels(-light));
  }
  // Light on the left at 60 deg: away is at 240 deg, so turn right with inner 12 cos 240.
  expect_wheels(run(module(13), model(Vec2::polar(1.0, kPi / 3.0), {})), {kFull, -6.0, 0}, 1e-12);
}

TEST(ModulesAntiPhototaxis, ObstacleTermIsFiveTimesTheProximityVector) {
  const Vec2 light = Vec2::polar(1.0, kPi);  // light behind: go forward...
  const Vec2 obstacle{0.1, 0.1};             // ...but an obstacle front-left
  const Vec2 v{1.0 - 0.5, -0.5};
  expect_wheels(run(module(13), model(light, obstacle)), spec_wheels(v));
  expect_wheels(run(module(13), model({}, {})), kStraight);
}

TEST(ModulesAttraction, FollowsTheNeighbourVectorScaledByAtt) {
  const Vec2 sum = Vec2::polar(0.05, degrees_to_radians(100));
  expect_wheels(run(module(14, {5}), model({}, {}, sum)), spec_wheels(sum * 5.0));
  // Alone (no neighbours, no obstacle): straight.
  expect_wheels(run(module(14, {5}), model({}, {})), kStraight);
  // A faint neighbour (|att * sum| < 0.1) is ignored: straight.
  expect_wheels(run(module(14, {1}), model({}, {}, Vec2::polar(0.05, 2.0))), kStraight);
}

TEST(ModulesAttraction, AttIsTruncatedToAnInteger) {
  // v = floor(att) * S - 6 Pv with S = (0, 0.05), Pv = (0.1, 0).
  const ReferenceModel rm = model({}, {0.1, 0.0}, {0.0, 0.05});
  const Actuation four = run(module(14, {4}), rm);
  expect_wheels(four, spec_wheels({-0.6, 0.2}));
  const Actuation almost_five = run(module(14, {4.99}), rm);
  EXPECT_EQ(almost_five.left_cm, four.left_cm);
  EXPECT_EQ(almost_five.right_cm, four.right_cm);
  const Actuation five = run(module(14, {5}), rm);
  expect_wheels(five, spec_wheels({-0.6, 0.25}));
  EXPECT_GT(std::abs(five.left_cm - four.left_cm), 0.1);
}

TEST(ModulesAttraction, ObstacleTermIsSixTimesTheProximityVector) {
  // S = (0, 1), att 1, Pv = (0.5, 0): v = (-3, 1) (with a factor 5 it would be (-2.5, 1)).
  const Actuation a = run(module(14, {1}), model({}, {0.5, 0.0}, {0.0, 1.0}));
  expect_wheels(a, spec_wheels({-3.0, 1.0}));
  EXPECT_EQ(a.right_cm, kFull);
  EXPECT_NEAR(a.left_cm, kFull * -3.0 / std::sqrt(10.0), 1e-12);
}

TEST(ModulesRepulsion, StrengthGrowsWithTheSquareOfRep) {
  // v = -rep^2 S - 5 Pv with S = (0, 0.1), Pv = (0.2, 0).
  const ReferenceModel rm = model({}, {0.2, 0.0}, {0.0, 0.1});
  const Actuation two = run(module(15, {2}), rm);
  const Actuation four = run(module(15, {4}), rm);
  expect_wheels(two, spec_wheels({-1.0, -0.4}));
  expect_wheels(four, spec_wheels({-1.0, -1.6}));
  // Proportional to rep (not rep^2) would give (-1, -0.2) and (-1, -0.4): clearly different.
  EXPECT_GT(std::abs(two.right_cm - spec_wheels({-1.0, -0.2}).right_cm), 0.1);
  EXPECT_GT(std::abs(four.right_cm - spec_wheels({-1.0, -0.4}).right_cm), 0.1);
}

TEST(ModulesRepulsion, RepIsTruncatedToAnInteger) {
  const ReferenceModel rm = model({}, {0.2, 0.0}, {0.0, 0.1});
  const Actuation two = run(module(15, {2}), rm);
  const Actuation almost_three = run(module(15, {2.99}), rm);
  EXPECT_EQ(almost_three.left_cm, two.left_cm);
  EXPECT_EQ(almost_three.right_cm, two.right_cm);
}

TEST(ModulesRepulsion, QuadraticGainLiftsAWeakSignalAboveTheFallback) {
  // |S| = 0.03 at 30 deg: rep 2 gives |v| = 0.12 away from it (a linear gain, 0.06, would fall
  // back to straight ahead).
  const Vec2 sum = Vec2::polar(0.03, degrees_to_radians(30));
  expect_wheels(run(module(15, {2}), model({}, {}, sum)), spec_wheels(sum * -4.0));
  EXPECT_LT(run(module(15, {2}), model({}, {}, sum)).right_cm, 0.0);  // 210 deg: spin right
  expect_wheels(run(module(15, {1}), model({}, {}, sum)), kStraight);
}

}  // namespace
}  // namespace sd
