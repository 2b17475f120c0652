// Behaviour trees: both grammars (Maple's --rootnode format and the BehaviorTree branch's
// --nroot format) and the tick semantics of ARGoS3-AutoMoDe's BehaviorTree branch, on a
// scripted reference model.
#include <gtest/gtest.h>

#include "control/config_string.hpp"
#include "control/describe.hpp"
#include "control/swarm_controller.hpp"
#include "control_test_helpers.hpp"
#include "modules/conditions.hpp"

namespace sd {
namespace {

using test::module;

BtNode composite(BtNodeType type, std::initializer_list<int> children) { return {type, children, {}, 0.0}; }
BtNode action(ModuleInstance m, double p = 0.0) { return {BtNodeType::Action, {}, m, p}; }
BtNode condition(ModuleInstance m) { return {BtNodeType::Condition, {}, m, 0.0}; }

ControlSoftware tree(std::initializer_list<BtNode> nodes) {
  ControlSoftware s;
  s.architecture = Architecture::BehaviourTree;
  s.bt.nodes = nodes;
  return s;
}

TEST(BehaviourTreeGrammar, SpecExampleFormatB) {
  // The example "seen in public use" (legacy one-digit ids, Chocolate by default).
  const auto s = parse_control_software(std::string(
      "--bt-config --nroot 3 --nchildroot 1 --n0 0 --nchild0 2 --n00 6 --c00 5 --p00 0.26 --n01 5 --a01 0 --rwm01 5 --p01 0"));
  const auto expected = tree({composite(BtNodeType::SequenceStar, {1}), composite(BtNodeType::Selector, {2, 3}),
                              condition(module(15, {0.26})), action(module(10, {5}))});
  EXPECT_EQ(s, expected);
  EXPECT_EQ(to_config_string(s),
            "--bt-config --nroot 3 --nchildroot 1 --n0 0 --nchild0 2 --n00 6 --c00 15 --p00 0.26 --n01 5 --a01 10 --rwm01 5 --p01 0");
}

TEST(BehaviourTreeGrammar, MapleFormatAReadsAsTheSameTreeAsFormatB) {
  ParseOptions maple;
  maple.legacy_flavour = Flavour::Maple;
  const auto a = parse_control_software(
      std::string("--rootnode 0 --nchildsroot 2 --n0 0 --nc0 1 --c0x0 0 --p0x0 0.27 --a0 4 --att0 4.93 --n1 0 --nc1 1 "
                  "--c1x0 1 --p1x0 0.88 --a1 2"),
      maple);
  const auto b = parse_control_software(
      std::string("--bt-config --nroot 3 --nchildroot 2 --n0 0 --nchild0 2 --n00 6 --c00 40 --p00 0.27 --n01 5 --a01 44 "
                  "--att01 4.93 --p01 0 --n1 0 --nchild1 2 --n10 6 --c10 41 --p10 0.88 --n11 5 --a11 42 --p11 0"));
  EXPECT_EQ(a, b);
}

TEST(BehaviourTreeGrammar, MixedFlavoursRoundTrip) {
  // A TuttiFrutti action and a Coconut condition under a negation and a Selector*.
  const auto t = tree({composite(BtNodeType::SelectorStar, {1, 4}), composite(BtNodeType::Negation, {2}),
                       composite(BtNodeType::Sequence, {3}), condition(module(33, {4, 2.5})),
                       action(module(28, {1, 4, 2}), 0.125)});
  const std::string text = to_config_string(t);
  EXPECT_EQ(parse_control_software(text), t) << text;
  EXPECT_EQ(to_config_string(parse_control_software(text)), text);
  EXPECT_NE(describe(t).find("GoToColor[28](vel=1, cle=4, clr=2) [succeeds with p=0.125]"), std::string::npos) << describe(t);
  EXPECT_NE(to_dot(t).find("n0 -> n4"), std::string::npos);
}

/// A scripted robot: only the ground reading matters to these trees.
struct Robot {
  ReferenceModel rm;
  Rng rng{1};
  Actuation step(SwarmController& c, double ground) {
    rm.ground = ground;
    rm.light = {1.0, 0.0};
    return c.step(0, rm, rng);
  }
};

// Maple: Sequence*( Selector(BlackFloor?, Phototaxis), Selector(WhiteFloor?, Anti-phototaxis) ).
const ControlSoftware kMaple = tree({composite(BtNodeType::SequenceStar, {1, 4}), composite(BtNodeType::Selector, {2, 3}),
                                     condition(module(40, {1.0})), action(module(42)),
                                     composite(BtNodeType::Selector, {5, 6}), condition(module(42, {1.0})),
                                     action(module(43))});

TEST(BehaviourTreeTicks, SequenceStarStaysOnABranchUntilItsConditionHolds) {
  SwarmController c(kMaple, 1);
  Robot r;
  // Gray: branch 0's condition fails, its action (phototaxis towards +x) runs.
  Actuation a = r.step(c, 0.5);
  EXPECT_EQ(c.current_state(0), 3);
  EXPECT_DOUBLE_EQ(a.left_cm, 12.0);
  EXPECT_DOUBLE_EQ(a.right_cm, 12.0);
  // Black: branch 0 succeeds and branch 1 runs in the same step (anti-phototaxis).
  a = r.step(c, 0.0);
  EXPECT_EQ(c.current_state(0), 6);
  EXPECT_DOUBLE_EQ(a.left_cm, 12.0);
  EXPECT_DOUBLE_EQ(a.right_cm, -6.0);  // turning away from the light ahead, inner wheel >= -6 (BT branch)
  // Still black: the Sequence* remembers branch 1.
  r.step(c, 0.0);
  EXPECT_EQ(c.current_state(0), 6);
  // White: branch 1 succeeds, the tree succeeds, the robot stops for this step...
  a = r.step(c, 1.0);
  EXPECT_EQ(a.left_cm, 0.0);
  EXPECT_EQ(a.right_cm, 0.0);
  EXPECT_EQ(c.current_state(0), -1);  // no action ran at this step
  // ... and the next step starts again from branch 0.
  r.step(c, 0.5);
  EXPECT_EQ(c.current_state(0), 3);
}

TEST(BehaviourTreeTicks, SelectorStarSucceedsWhenAllChildrenFail) {
  // Selector*( BlackFloor? , WhiteFloor? ) on gray: both fail -> success -> stop.
  const auto t = tree({composite(BtNodeType::SelectorStar, {1, 2}), condition(module(10, {1.0})), condition(module(12, {1.0}))});
  SwarmController c(t, 1);
  Robot r;
  const Actuation a = r.step(c, 0.5);
  EXPECT_EQ(a.left_cm, 0.0);
  EXPECT_EQ(c.current_state(0), -1);  // no action ran
}

TEST(BehaviourTreeTicks, NegationSwapsSuccessAndFailure) {
  // Sequence( Not(BlackFloor?), Stop ) runs Stop off black; on black the sequence fails.
  const auto t = tree({composite(BtNodeType::Sequence, {1, 3}), composite(BtNodeType::Negation, {2}),
                       condition(module(10, {1.0})), action(module(21, {4}))});
  SwarmController c(t, 1);
  Robot r;
  Actuation a = r.step(c, 0.5);
  EXPECT_EQ(c.current_state(0), 3);
  EXPECT_EQ(a.led, 0xffff00u);  // TuttiFrutti Stop shows yellow (cle 4)
  a = r.step(c, 0.0);
  EXPECT_EQ(a.left_cm, 0.0);
  EXPECT_EQ(a.led, kLedUnchanged);  // no action ran: the LEDs keep their colour
}

TEST(BehaviourTreeTicks, AnActionThatSucceedsDoesNotRun) {
  // Sequence( Exploration succeeding with p = 1, Stop ): Stop runs every step.
  const auto t = tree({composite(BtNodeType::Sequence, {1, 2}), action(module(10, {5}), 1.0), action(module(11))});
  SwarmController c(t, 1);
  Robot r;
  for (int k = 0; k < 5; ++k) {
    const Actuation a = r.step(c, 0.5);
    EXPECT_EQ(c.current_state(0), 2);
    EXPECT_EQ(a.left_cm, 0.0);
  }
}

TEST(BehaviourTreeTicks, NeighbourConditionsDrawWithTheirOwnLogistic) {
  // Selector( Sequence(NeighborsCount(2, 1.5)?, Stop), Sequence(InvertedNeighborsCount(5, 0.4)?,
  // Stop) ) in a swarm of four: the controller tabulates each logistic for 0 .. 3 neighbours.
  // Step for step the robot must draw and act as the functions themselves say, for counts
  // beyond its tables too.
  const auto t = tree({composite(BtNodeType::Selector, {1, 4}), composite(BtNodeType::Sequence, {2, 3}),
                       condition(module(13, {2, 1.5})), action(module(11)), composite(BtNodeType::Sequence, {5, 6}),
                       condition(module(14, {5, 0.4})), action(module(11))});
  SwarmController c(t, 4);
  Rng rng(47), expected(47);
  ReferenceModel rm;
  int ran, first = 0, second = 0;
  for (int k = 0; k < 3000; ++k) {
    rm.neighbours = k % 7;
    c.step(2, rm, rng);
    ran = -1;
    if (expected.bernoulli(neighbours_probability(2, 1.5, rm.neighbours))) {
      ran = 3;
      ++first;
    } else if (expected.bernoulli(1.0 - neighbours_probability(5, 0.4, rm.neighbours))) {
      ran = 6;
      ++second;
    }  // else the tree failed: no action ran
    ASSERT_EQ(c.current_state(2), ran) << "step " << k;
    ASSERT_TRUE(test::same_rng_state(rng, expected)) << "step " << k;
  }
  EXPECT_GT(first, 300);
  EXPECT_GT(second, 300);
}

}  // namespace
}  // namespace sd
