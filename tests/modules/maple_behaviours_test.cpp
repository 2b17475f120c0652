// Maple's actions (ids 40-45) follow the behaviour-tree code base (ARGoS3-AutoMoDe branch
// BehaviorTree, dd7167c), not master: W(v) keeps the
// inner wheel at or above -0.5 x 12 cm/s, Exploration turns only at a reading >= 0.5 in front,
// and Repulsion applies rep once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "modules/maple_behaviours.hpp"
#include "module_test_helpers.hpp"

namespace sd {
namespace {

using test::expect_wheels;
using test::kFull;
using test::module;

/// W(v) of the BT branch restated: theta = UnsignedNormalize(angle of v); 0 < theta < pi turns
/// left (right wheel 12, left 12 max(-0.5, cos theta)), anything else turns right.
Actuation bt_wheels(Vec2 v) {
  const double theta = wrap_unsigned(std::atan2(v.y, v.x));
  const double inner = kFull * std::max(-0.5, std::cos(theta));
  if (theta > 0.0 && theta < kPi) return {inner, kFull, 0};
  return {kFull, inner, 0};
}

ReferenceModel obstacle_at(double length, double degrees) {
  ReferenceModel rm;
  rm.proximity = Vec2::polar(length, degrees_to_radians(degrees));
  return rm;
}

TEST(MapleWheels, InnerWheelNeverBelowMinusSix) {
  expect_wheels(maple::bounded_wheels_towards({-1.0, 0.0}), {kFull, -6.0, 0});                      // straight behind
  expect_wheels(maple::bounded_wheels_towards(Vec2::polar(1.0, degrees_to_radians(150))), {-6.0, kFull, 0});
  expect_wheels(maple::bounded_wheels_towards(Vec2::polar(1.0, degrees_to_radians(-135))), {kFull, -6.0, 0});
  // Within +-120 degrees the bound does not act: the law is Chocolate's.
  expect_wheels(maple::bounded_wheels_towards(Vec2::polar(1.0, degrees_to_radians(100))),
                {kFull * std::cos(degrees_to_radians(100)), kFull, 0}, 1e-12);
  expect_wheels(maple::bounded_wheels_towards({0.0, 0.0}), {0.0, 0.0, 0});
}

TEST(MapleWheels, EveryDirectionMatchesTheBtFormula) {
  for (int deg = -179; deg <= 180; deg += 7) {
    const Vec2 v = Vec2::polar(2.5, degrees_to_radians(deg));
    SCOPED_TRACE(testing::Message() << deg << " deg");
    expect_wheels(maple::bounded_wheels_towards(v), bt_wheels(v));
  }
}

TEST(MapleActions, VectorLawsUseTheBoundedWheels) {
  ReferenceModel rm;
  rm.light = Vec2::polar(1.0, degrees_to_radians(170));  // light behind on the left
  rm.proximity = Vec2::polar(0.05, 0.3);
  rm.rab_steps[0] = Vec2::polar(0.1, degrees_to_radians(-160));  // every vector below is longer than 0.1
  Rng rng(3);
  BehaviourMemory m;
  expect_wheels(run_behaviour(module(42), m, rm, rng), bt_wheels(rm.light - rm.proximity * 5.0));
  expect_wheels(run_behaviour(module(43), m, rm, rng), bt_wheels(-rm.light - rm.proximity * 5.0));
  expect_wheels(run_behaviour(module(44, {4.7}), m, rm, rng), bt_wheels(rm.attraction(4.0) - rm.proximity * 6.0));
  // Repulsion: rep enters once, inside A(rep) (Chocolate: twice).
  expect_wheels(run_behaviour(module(45, {4.9}), m, rm, rng), bt_wheels(-rm.attraction(4.0) - rm.proximity * 5.0));
  expect_wheels(run_behaviour(module(41), m, rm, rng), {0.0, 0.0, 0});
  // The phototaxis that turns around spins less hard than Chocolate's.
  const Actuation chocolate = run_behaviour(module(12), m, rm, rng);
  const Actuation maple = run_behaviour(module(42), m, rm, rng);
  EXPECT_LT(chocolate.left_cm, -6.0);
  EXPECT_EQ(maple.left_cm, -6.0);
}

TEST(MapleExploration, IgnoresReadingsBelowOneHalf) {
  // Chocolate turns at these readings; the BT branch's Exploration drives on and draws nothing.
  for (const ReferenceModel& rm : {obstacle_at(0.1, 0), obstacle_at(0.3, -20), obstacle_at(0.499, 40)}) {
    Rng rng(7);
    const Rng before = rng;
    BehaviourMemory memory;
    for (int k = 0; k < 5; ++k) expect_wheels(run_behaviour(module(40, {50}), memory, rm, rng), {kFull, kFull, 0});
    EXPECT_TRUE(test::same_rng_state(rng, before));
    BehaviourMemory chocolate;
    run_behaviour(module(10, {50}), chocolate, rm, rng);
    EXPECT_TRUE(chocolate.turning);
  }
}

TEST(MapleExploration, TurnsAwayFromAReadingOfOneHalfInFront) {
  for (const double degrees : {-30.0, 0.0, 60.0}) {
    Rng rng(11), copy(11);
    const int drawn = std::max<int>(static_cast<int>(copy.uniform_int(0, 20)), 1);
    BehaviourMemory memory;
    const ReferenceModel seen = obstacle_at(0.5, degrees), free{};
    expect_wheels(run_behaviour(module(40, {20}), memory, seen, rng), {kFull, kFull, 0});  // detection step
    const bool left = degrees < 0.0;  // obstacle on the right: turn left
    int steps = 0;
    for (; steps < 100; ++steps) {
      const Actuation a = run_behaviour(module(40, {20}), memory, free, rng);
      if (a.left_cm == kFull && a.right_cm == kFull) break;
      expect_wheels(a, left ? Actuation{-kFull, kFull, 0} : Actuation{kFull, -kFull, 0});
    }
    EXPECT_EQ(steps, drawn) << degrees;
  }
}

TEST(MapleExploration, ObstacleBehindStartsNoTurn) {
  Rng rng(13);
  BehaviourMemory memory;
  run_behaviour(module(40, {50}), memory, obstacle_at(1.0, 120), rng);
  EXPECT_FALSE(memory.turning);
}

}  // namespace
}  // namespace sd
