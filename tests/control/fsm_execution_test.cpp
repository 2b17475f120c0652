// FSM execution semantics (ARGoS3-AutoMoDe's AutoMoDeFiniteStateMachine::ControlStep): no
// condition on the entry step, the old state's command on the firing step, behaviour reset on
// entry, random order of outgoing transitions with the first that fires winning.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "control/swarm_controller.hpp"
#include "control_test_helpers.hpp"
#include "modules/conditions.hpp"

namespace sd {
namespace {

using test::fsm;
using test::module;
using test::same_rng_state;
using test::state;
using test::transition;

constexpr double kFull = 12.0;

/// A reference model with nothing in view: gray floor, no light, no obstacle, no neighbour.
ReferenceModel quiet() { return ReferenceModel{}; }

ReferenceModel with_ground(double g) {
  ReferenceModel rm;
  rm.ground = g;
  return rm;
}

/// |observed - n p| within 5 standard deviations of a binomial count.
void expect_binomial(int observed, int n, double p) {
  const double mean = n * p;
  const double sigma = std::sqrt(n * p * (1.0 - p));
  EXPECT_NEAR(observed, mean, 5.0 * sigma) << "observed " << observed << " of " << n << ", expected p = " << p;
}

TEST(ControlFsmExecution, CertainTransitionFiresOnTheSecondStepOfAState) {
  // 0 (Stop) --p=1--> 1 (Exploration) --p=1--> 0.
  const ControlSoftware software = fsm({state(module(11), {transition(1, module(15, {1.0}))}),
                                        state(module(10, {10}), {transition(0, module(15, {1.0}))})});
  SwarmController controller(software, 1);
  Rng rng(7);
  const ReferenceModel rm = quiet();
  // Each state runs two steps: the entry step (no condition) and the step where p = 1 fires.
  const std::vector<int> state_after = {0, 1, 1, 0, 0, 1, 1, 0};
  const std::vector<double> left_wheel = {0, 0, kFull, kFull, 0, 0, kFull, kFull};  // Stop, Stop, Exploration, ...
  for (std::size_t k = 0; k < state_after.size(); ++k) {
    const Actuation a = controller.step(0, rm, rng);
    EXPECT_EQ(controller.current_state(0), state_after[k]) << "after step " << k + 1;
    EXPECT_EQ(a.left_cm, left_wheel[k]) << "step " << k + 1;
    EXPECT_EQ(a.right_cm, left_wheel[k]) << "step " << k + 1;
  }
}

TEST(ControlFsmExecution, EntryStepDrawsNoRandomNumber) {
  const ControlSoftware software = fsm({state(module(11), {transition(1, module(15, {0.5})), transition(1, module(15, {0.5}))}),
                                        state(module(11))});
  SwarmController controller(software, 1);
  Rng rng(11);
  const Rng before = rng;
  controller.step(0, quiet(), rng);
  EXPECT_TRUE(same_rng_state(rng, before)) << "a condition was evaluated (or shuffled) on the entry step";
  controller.step(0, quiet(), rng);
  EXPECT_FALSE(same_rng_state(rng, before)) << "no condition evaluated on the second step";
}

TEST(ControlFsmExecution, FiringStepAppliesTheOldStatesCommand) {
  // Light on the left: Phototaxis turns left (right wheel 12), Anti-phototaxis turns right.
  const ControlSoftware software = fsm({state(module(12), {transition(1, module(15, {1.0}))}),
                                        state(module(13), {transition(0, module(15, {1.0}))})});
  SwarmController controller(software, 1);
  Rng rng(3);
  ReferenceModel rm;
  rm.light = Vec2::polar(1.0, kPi / 3.0);
  const double inner = kFull * std::cos(kPi / 3.0);

  Actuation a = controller.step(0, rm, rng);  // enter 0
  EXPECT_NEAR(a.left_cm, inner, 1e-12);
  EXPECT_EQ(a.right_cm, kFull);
  a = controller.step(0, rm, rng);  // 0 -> 1 fires: still Phototaxis' command
  ASSERT_EQ(controller.current_state(0), 1);
  EXPECT_NEAR(a.left_cm, inner, 1e-12);
  EXPECT_EQ(a.right_cm, kFull);
  a = controller.step(0, rm, rng);  // enter 1: Anti-phototaxis, light behind on the left -> turn right
  EXPECT_EQ(a.left_cm, kFull);
  EXPECT_NEAR(a.right_cm, kFull * std::cos(kPi / 3.0 + kPi), 1e-12);
}

/// Number of in-place left-turn steps an Exploration(rwm) makes after seeing an obstacle on
/// its right at the first step, with this seed.
int exploration_turn_length(std::uint64_t seed, double rwm, const ReferenceModel& obstacle) {
  const ControlSoftware alone = fsm({state(module(10, {rwm}))});
  SwarmController controller(alone, 1);
  Rng rng(seed);
  controller.step(0, obstacle, rng);
  int turning = 0;
  while (turning < 200 && controller.step(0, quiet(), rng).left_cm < 0.0) ++turning;
  return turning;
}

TEST(ControlFsmExecution, BehaviourMemoryIsResetWhenAStateIsEntered) {
  ReferenceModel obstacle_right;
  obstacle_right.proximity = Vec2::polar(0.5, -kPi / 6.0);
  // A seed whose first turn lasts at least 4 steps, found (not assumed) with a lone Exploration.
  std::uint64_t seed = 1;
  while (exploration_turn_length(seed, 100, obstacle_right) < 4) ++seed;

  // 0 Exploration --black--> 1 Stop --white--> 0.
  const ControlSoftware software = fsm({state(module(10, {100}), {transition(1, module(10, {1.0}))}),
                                        state(module(11), {transition(0, module(12, {1.0}))})});
  SwarmController controller(software, 1);
  Rng rng(seed);
  Actuation a = controller.step(0, obstacle_right, rng);  // enter 0, sees the obstacle: turn starts next step
  EXPECT_EQ(a.left_cm, kFull);
  a = controller.step(0, with_ground(0.0), rng);  // turning left; black floor -> leave to 1
  EXPECT_EQ(a.left_cm, -kFull);
  EXPECT_EQ(a.right_cm, kFull);
  ASSERT_EQ(controller.current_state(0), 1);
  controller.step(0, quiet(), rng);                 // enter 1
  controller.step(0, with_ground(1.0), rng);        // white floor -> back to 0
  ASSERT_EQ(controller.current_state(0), 0);
  a = controller.step(0, quiet(), rng);             // re-enter 0: the unfinished turn is forgotten
  EXPECT_EQ(a.left_cm, kFull);
  EXPECT_EQ(a.right_cm, kFull);
}

/// Coconut behaviour `id` with exp 1 (a random turn of up to rwm = 100 steps); attraction and
/// repulsion take att / rep 1 first.
ModuleInstance coconut_random_turn(int id) { return id == 34 || id == 35 ? module(id, {1, 1, 100}) : module(id, {1, 100}); }

/// Steps a lone Coconut behaviour `id` spins in place after seeing an obstacle on its right at
/// the first step, with this seed.
int coconut_spin_length(int id, std::uint64_t seed, const ReferenceModel& obstacle) {
  const ControlSoftware alone = fsm({state(coconut_random_turn(id))});
  SwarmController controller(alone, 1);
  Rng rng(seed);
  int spinning = controller.step(0, obstacle, rng).left_cm < 0.0 ? 1 : 0;
  while (spinning < 200 && controller.step(0, quiet(), rng).left_cm < 0.0) ++spinning;
  return spinning;
}

/// Whether Coconut behaviour `id` still spins when its state is entered again, two states
/// after the spin began: 0 (id) --p=1--> 1 (Stop) --p=1--> 0.
bool coconut_spins_on_reentry(int id, std::uint64_t seed, const ReferenceModel& obstacle) {
  const ControlSoftware software = fsm({state(coconut_random_turn(id), {transition(1, module(35, {1.0}))}),
                                        state(module(31), {transition(0, module(35, {1.0}))})});
  SwarmController controller(software, 1);
  Rng rng(seed);
  EXPECT_LT(controller.step(0, obstacle, rng).left_cm, 0.0);  // enter 0: the spin starts
  EXPECT_LT(controller.step(0, quiet(), rng).left_cm, 0.0);   // still spinning; leaves to 1
  controller.step(0, quiet(), rng);                           // enter 1
  controller.step(0, quiet(), rng);                           // back to 0
  EXPECT_EQ(controller.current_state(0), 0);
  return controller.step(0, quiet(), rng).left_cm < 0.0;
}

TEST(ControlFsmExecution, CoconutBehavioursOtherThanExplorationKeepTheirCounterAcrossStates) {
  // Demiurge's Coconut: only Exploration (30) re-initialises its random-turn counter when its
  // state is entered; phototaxis, anti-phototaxis, attraction and repulsion (32-35) keep it.
  ReferenceModel obstacle_right;
  obstacle_right.proximity = Vec2::polar(0.5, -kPi / 6.0);
  // A seed whose spin lasts at least 6 steps, found (not assumed) with a lone behaviour.
  std::uint64_t seed = 1;
  while (coconut_spin_length(32, seed, obstacle_right) < 6) ++seed;
  EXPECT_FALSE(coconut_spins_on_reentry(30, seed, obstacle_right)) << "Exploration starts afresh";
  for (const int id : {32, 33, 34, 35}) EXPECT_TRUE(coconut_spins_on_reentry(id, seed, obstacle_right)) << id;
}

TEST(ControlFsmExecution, TwoCertainTransitionsAreTakenEquallyOften) {
  const ControlSoftware software = fsm(
      {state(module(11), {transition(1, module(15, {1.0})), transition(2, module(15, {1.0}))}), state(module(11)),
       state(module(11))});
  SwarmController controller(software, 1);
  Rng rng(2024);
  const int trials = 20000;
  int to_one = 0, to_two = 0;
  for (int t = 0; t < trials; ++t) {
    controller.reset();
    controller.step(0, quiet(), rng);
    controller.step(0, quiet(), rng);
    const int s = controller.current_state(0);
    to_one += s == 1;
    to_two += s == 2;
  }
  EXPECT_EQ(to_one + to_two, trials);
  expect_binomial(to_one, trials, 0.5);
}

TEST(ControlFsmExecution, LeaveProbabilityWithTwoTransitionsIsOneMinusProductOfMisses) {
  const double p1 = 0.3, p2 = 0.5;
  const ControlSoftware software = fsm(
      {state(module(11), {transition(1, module(15, {p1})), transition(2, module(15, {p2}))}), state(module(11)),
       state(module(11))});
  SwarmController controller(software, 1);
  Rng rng(99);
  const int trials = 40000;
  int to_one = 0, to_two = 0;
  for (int t = 0; t < trials; ++t) {
    controller.reset();
    controller.step(0, quiet(), rng);
    controller.step(0, quiet(), rng);
    to_one += controller.current_state(0) == 1;
    to_two += controller.current_state(0) == 2;
  }
  expect_binomial(to_one + to_two, trials, 1.0 - (1.0 - p1) * (1.0 - p2));
  // Each order has probability 1/2; the first transition tried wins if it fires.
  expect_binomial(to_one, trials, 0.5 * p1 + 0.5 * (1.0 - p2) * p1);
  expect_binomial(to_two, trials, 0.5 * p2 + 0.5 * (1.0 - p1) * p2);
}

/// How many 64-bit draws separate `before` from `after` (-1 if more than 64).
int draws_between(const Rng& before, const Rng& after) {
  Rng r = before;
  for (int n = 0; n <= 64; ++n, r.next())
    if (same_rng_state(r, after)) return n;
  return -1;
}

/// Draws consumed by the first non-entry step of a state with two FixedProbability(p)
/// transitions.
int draws_of_second_step(double p) {
  const ControlSoftware software = fsm(
      {state(module(11), {transition(1, module(15, {p})), transition(1, module(15, {p}))}), state(module(11))});
  SwarmController controller(software, 1);
  Rng rng(17);
  controller.step(0, quiet(), rng);
  const Rng before = rng;
  controller.step(0, quiet(), rng);
  return draws_between(before, rng);
}

TEST(ControlFsmExecution, ConditionsAfterTheFirstThatFiresAreNotEvaluated) {
  // With p = 0 both conditions are evaluated; with p = 1 the first fires and the second is
  // never drawn, so the step consumes exactly one draw less (the shuffle costs the same).
  const int none_fire = draws_of_second_step(0.0);
  const int first_fires = draws_of_second_step(1.0);
  ASSERT_GE(none_fire, 2);
  EXPECT_EQ(first_fires, none_fire - 1);
}

TEST(ControlFsmExecution, StateWithoutTransitionsIsNeverLeft) {
  const ControlSoftware software = fsm({state(module(11), {transition(1, module(15, {1.0}))}), state(module(12))});
  SwarmController controller(software, 1);
  Rng rng(5);
  for (int k = 0; k < 50; ++k) controller.step(0, quiet(), rng);
  EXPECT_EQ(controller.current_state(0), 1);
}

TEST(ControlFsmExecution, RobotsRunIndependentlyAndResetReturnsToStateZero) {
  const ControlSoftware software = fsm({state(module(11), {transition(1, module(15, {1.0}))}),
                                        state(module(11), {transition(0, module(15, {1.0}))})});
  SwarmController controller(software, 3);
  Rng rng(1);
  controller.step(1, quiet(), rng);
  controller.step(1, quiet(), rng);
  EXPECT_EQ(controller.current_state(0), 0);
  EXPECT_EQ(controller.current_state(1), 1);
  EXPECT_EQ(controller.current_state(2), 0);
  // Robot 0 starts on its own entry step: one step does not leave state 0.
  controller.step(0, quiet(), rng);
  EXPECT_EQ(controller.current_state(0), 0);
  controller.reset();
  EXPECT_EQ(controller.current_state(1), 0);
  controller.step(1, quiet(), rng);  // entry step again after reset
  EXPECT_EQ(controller.current_state(1), 0);
}

TEST(ControlFsmExecution, ConditionsSeeTheReferenceModelOfTheCurrentStep) {
  // BlackFloor p=1 does not fire on gray and fires on the first non-entry black step.
  const ControlSoftware software = fsm({state(module(11), {transition(1, module(10, {1.0}))}), state(module(11))});
  SwarmController controller(software, 1);
  Rng rng(8);
  for (int k = 0; k < 5; ++k) controller.step(0, with_ground(0.5), rng);
  EXPECT_EQ(controller.current_state(0), 0);
  controller.step(0, with_ground(0.0), rng);
  EXPECT_EQ(controller.current_state(0), 1);
}

TEST(ControlFsmExecution, NeighbourConditionsDrawWithTheirOwnLogistic) {
  // 0 --NeighborsCount(2, 1.5)--> 1 --InvertedNeighborsCount(5, 0.4)--> 0 in a swarm of four:
  // the controller tabulates each logistic for 0 .. 3 neighbours. Step for step the robot
  // must draw and move as the functions themselves say, for counts beyond its tables too.
  const ModuleInstance count = module(13, {2, 1.5}), inverted = module(14, {5, 0.4});
  const ControlSoftware software = fsm({state(module(11), {transition(1, count)}), state(module(11), {transition(0, inverted)})});
  SwarmController controller(software, 4);
  Rng rng(31), expected(31);
  ReferenceModel rm;
  int state_now = 0, moves = 0;
  bool entering = true;
  for (int k = 0; k < 3000; ++k) {
    rm.neighbours = k % 7;
    controller.step(2, rm, rng);
    if (entering) {
      entering = false;
    } else if (state_now == 0 ? expected.bernoulli(neighbours_probability(2, 1.5, rm.neighbours))
                              : expected.bernoulli(1.0 - neighbours_probability(5, 0.4, rm.neighbours))) {
      state_now = 1 - state_now;
      entering = true;
      ++moves;
    }
    ASSERT_EQ(controller.current_state(2), state_now) << "step " << k;
    ASSERT_TRUE(same_rng_state(rng, expected)) << "step " << k;
  }
  EXPECT_GT(moves, 300);
}

}  // namespace
}  // namespace sd
