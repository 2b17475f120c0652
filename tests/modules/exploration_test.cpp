// Exploration (ARGoS3-AutoMoDe master): straight on; an obstacle in front (|P| >= 0.1,
// angle in [-pi/2, pi/2]) starts an in-place turn away from it on the next step, lasting
// max(U{0..rwm-1}, 1) steps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "module_test_helpers.hpp"

namespace sd {
namespace {

using test::kFull;
using test::module;

ReferenceModel obstacle_at(double length, double degrees) {
  ReferenceModel rm;
  rm.proximity = Vec2::polar(length, degrees_to_radians(degrees));
  return rm;
}

ReferenceModel obstacle_vector(Vec2 p) {
  ReferenceModel rm;
  rm.proximity = p;
  return rm;
}

/// Runs one detection step with `seen`, then free steps; returns how many steps turned and
/// checks every turning step spins in place in the given direction.
int turn_length(double rwm, const ReferenceModel& seen, Rng& rng, bool expect_left) {
  BehaviourMemory memory;
  reset_behaviour(memory);
  const ModuleInstance exploration = module(10, {rwm});
  const Actuation first = run_behaviour(exploration, memory, seen, rng);
  EXPECT_EQ(first.left_cm, kFull);  // the detection step still drives forward
  EXPECT_EQ(first.right_cm, kFull);
  const ReferenceModel free{};
  int steps = 0;
  for (; steps < 1000; ++steps) {
    const Actuation a = run_behaviour(exploration, memory, free, rng);
    if (a.left_cm == kFull && a.right_cm == kFull) break;
    EXPECT_EQ(a.left_cm, expect_left ? -kFull : kFull);
    EXPECT_EQ(a.right_cm, expect_left ? kFull : -kFull);
  }
  return steps;
}

TEST(ModulesExploration, DrivesStraightWithoutObstacleAndDrawsNothing) {
  BehaviourMemory memory;
  Rng rng(1);
  const Rng before = rng;
  for (int k = 0; k < 20; ++k) {
    const Actuation a = run_behaviour(module(10, {50}), memory, ReferenceModel{}, rng);
    EXPECT_EQ(a.left_cm, kFull);
    EXPECT_EQ(a.right_cm, kFull);
  }
  EXPECT_TRUE(test::same_rng_state(rng, before));
}

TEST(ModulesExploration, ObstacleFrontRightTurnsLeftForTheDrawnNumberOfSteps) {
  Rng rng(42);
  for (int trial = 0; trial < 50; ++trial) {
    Rng copy = rng;
    const std::uint32_t drawn = copy.uniform_int(0, 20);  // ARGoS Uniform(CRange<UInt32>(0, rwm))
    const int expected = std::max<int>(static_cast<int>(drawn), 1);
    EXPECT_EQ(turn_length(20, obstacle_at(0.5, -30), rng, true), expected) << "trial " << trial;
  }
}

TEST(ModulesExploration, ObstacleFrontLeftTurnsRight) {
  Rng rng(43);
  EXPECT_GE(turn_length(20, obstacle_at(0.5, 30), rng, false), 1);
}

TEST(ModulesExploration, ObstacleStraightAheadTurnsRight) {
  // Direction is LEFT only if the obstacle angle is negative.
  Rng rng(44);
  EXPECT_GE(turn_length(20, obstacle_at(0.8, 0), rng, false), 1);
}

TEST(ModulesExploration, ObstacleExactlyAtTheSideCountsAsInFront) {
  Rng rng(45);
  EXPECT_GE(turn_length(20, obstacle_vector({0.0, -0.5}), rng, true), 1);  // angle -pi/2
  EXPECT_GE(turn_length(20, obstacle_vector({0.0, 0.5}), rng, false), 1);  // angle +pi/2
}

TEST(ModulesExploration, ObstacleBehindOrTooWeakStartsNoTurn) {
  Rng rng(46);
  for (const ReferenceModel& rm : {obstacle_at(1.0, 150), obstacle_at(1.0, -150), obstacle_at(1.0, 180),
                                   obstacle_vector({-1e-9, -0.5}), obstacle_at(0.099, 0), obstacle_at(0.05, -20)}) {
    BehaviourMemory memory;
    const Rng before = rng;
    for (int k = 0; k < 5; ++k) {
      const Actuation a = run_behaviour(module(10, {50}), memory, rm, rng);
      EXPECT_EQ(a.left_cm, kFull);
      EXPECT_EQ(a.right_cm, kFull);
    }
    EXPECT_TRUE(test::same_rng_state(rng, before));
  }
}

TEST(ModulesExploration, ObstacleOfLengthExactlyPointOneIsDetected) {
  Rng rng(47);
  EXPECT_GE(turn_length(20, obstacle_vector({0.1, 0.0}), rng, false), 1);
}

TEST(ModulesExploration, TurnLengthIsUniformOnOneToRwmWithMinimumOne) {
  // turnSteps ~ U{0, ..., rwm-1}; a draw of 0 still turns once. With rwm = 10:
  // P(1) = 2/10, P(k) = 1/10 for k = 2..9, never 10 or more.
  const int rwm = 10, trials = 20000;
  std::vector<int> counts(rwm + 1, 0);
  Rng rng(2025);
  for (int t = 0; t < trials; ++t) {
    const int length = turn_length(rwm, obstacle_at(0.4, -80), rng, true);
    ASSERT_GE(length, 1);
    ASSERT_LT(length, rwm);
    ++counts[static_cast<std::size_t>(length)];
  }
  test::expect_binomial(counts[1], trials, 2.0 / rwm);
  for (int k = 2; k < rwm; ++k) test::expect_binomial(counts[static_cast<std::size_t>(k)], trials, 1.0 / rwm);
}

TEST(ModulesExploration, RwmOneOrTwoAlwaysTurnsExactlyOneStep) {
  Rng rng(48);
  for (int t = 0; t < 200; ++t) {
    EXPECT_EQ(turn_length(1, obstacle_at(0.4, -10), rng, true), 1);
    EXPECT_EQ(turn_length(2, obstacle_at(0.4, 10), rng, false), 1);
  }
}

TEST(ModulesExploration, ResetForgetsAnUnfinishedTurn) {
  BehaviourMemory memory;
  Rng rng(49);
  // Keep seeing obstacles until a turn of at least 2 steps is armed.
  for (int k = 0; k < 100 && !(memory.turning && memory.turn_steps >= 2); ++k) {
    reset_behaviour(memory);
    run_behaviour(module(10, {100}), memory, obstacle_at(0.5, -30), rng);
  }
  ASSERT_TRUE(memory.turning);
  reset_behaviour(memory);
  const Actuation a = run_behaviour(module(10, {100}), memory, ReferenceModel{}, rng);
  EXPECT_EQ(a.left_cm, kFull);
  EXPECT_EQ(a.right_cm, kFull);
}

}  // namespace
}  // namespace sd
