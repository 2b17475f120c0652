// Arlequin modules as states of a finite-state machine and as actions of a behaviour tree,
// and an EvoStick network as the whole control software, evaluated on AAC.
#include <gtest/gtest.h>

#include <cmath>

#include "control/config_string.hpp"
#include "control/swarm_controller.hpp"
#include "evaluation/evaluator.hpp"
#include "evaluation/simulation.hpp"
#include "missions/catalogue.hpp"
#include "robot/reference_model_test_helpers.hpp"

namespace sd {
namespace {

// Exploration until a black floor (p 0.5), then Phototaxis until chance (p 0.1) sends it back.
const std::string kFsm =
    "--fsm-config --nstates 2 --s0 50 --n0 1 --n0x0 0 --c0x0 50 --p0x0 0.5 "
    "--s1 52 --n1 1 --n1x0 0 --c1x0 55 --p1x0 0.1";
// Maple topology: on black stop; otherwise attraction while neighbours are around; else explore.
const std::string kTree =
    "--bt-config --nroot 3 --nchildroot 3 "
    "--n0 0 --nchild0 2 --n00 6 --c00 50 --p00 0.9 --n01 5 --a01 51 --p01 0 "
    "--n1 0 --nchild1 2 --n10 6 --c10 53 --p10 2 --w10 5 --n11 5 --a11 54 --p11 0 "
    "--n2 0 --nchild2 2 --n20 6 --c20 55 --p20 0.2 --n21 5 --a21 50 --p21 0";

std::vector<double> scores_of(const std::string& config, int threads) {
  const Mission aac = load_mission("aac");
  const ControlSoftware software = parse_control_software(config);
  std::vector<EvaluationTask> tasks;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) tasks.push_back({&software, seed});
  std::vector<double> scores(tasks.size());
  ThreadedEvaluator(threads).evaluate(aac, tasks, scores);
  return scores;
}

void expect_valid_aac_scores(const std::vector<double>& scores) {
  for (const double s : scores) {
    EXPECT_TRUE(std::isfinite(s));
    EXPECT_GE(s, 0.0);
    EXPECT_LE(s, 20.0 * 1200.0);
    EXPECT_EQ(s, std::floor(s)) << "AAC counts robots per tick";
  }
}

TEST(ArlequinInControlSoftware, AnFsmOfArlequinModulesEvaluatesOnAac) {
  const auto one = scores_of(kFsm, 1);
  expect_valid_aac_scores(one);
  EXPECT_EQ(one, scores_of(kFsm, 2));
  EXPECT_EQ(to_config_string(parse_control_software(kFsm)), kFsm);
}

TEST(ArlequinInControlSoftware, ABehaviourTreeOfArlequinModulesEvaluatesOnAac) {
  const auto one = scores_of(kTree, 1);
  expect_valid_aac_scores(one);
  EXPECT_EQ(one, scores_of(kTree, 2));
  EXPECT_EQ(to_config_string(parse_control_software(kTree)), kTree);
}

TEST(ArlequinInControlSoftware, ArlequinMixesWithOtherFlavours) {
  // Chocolate exploration, Arlequin phototaxis on an Arlequin condition, Coconut stop.
  const std::string mixed =
      "--fsm-config --nstates 3 --s0 10 --rwm0 30 --n0 1 --n0x0 0 --c0x0 51 --p0x0 0.3 "
      "--s1 52 --n1 1 --n1x0 1 --c1x0 12 --p1x0 0.8 --s2 31";
  expect_valid_aac_scores(scores_of(mixed, 2));
}

TEST(ArlequinInControlSoftware, EnteringAnArlequinStateKeepsTheRangeAndBearingBuffer) {
  // DEMI clears the RAB buffer whenever a Harlequin state is entered; we do not. State 0
  // (Stop network) leaves for state 1 (Attraction network) with probability 1; on the step
  // after, state 1 must see the messages heard while state 0 ran.
  const ControlSoftware software = parse_control_software(
      std::string("--fsm-config --nstates 2 --s0 51 --n0 1 --n0x0 0 --c0x0 55 --p0x0 1 --s1 54"));
  SwarmController controller(software, 3);
  SwarmState swarm = test::silent_swarm(3);
  ReferenceModel rm;
  Rng rng(1);
  test::set_packets(swarm, 0, {{12.0, 0.8, 1}, {30.0, -1.2, 2}});
  rm.update(swarm, 0);
  controller.step(0, rm, rng);  // enters state 0: no condition checked
  test::set_packets(swarm, 0, {});
  rm.update(swarm, 0);
  controller.step(0, rm, rng);  // FixedProbability(1) fires
  ASSERT_EQ(controller.current_state(0), 1);
  rm.update(swarm, 0);
  ASSERT_EQ(rm.buffered_messages(), 2);
  const Actuation a = controller.step(0, rm, rng);  // entering state 1
  const Actuation expected = arlequin::drive(arlequin::shipped_weights(54), rm);
  EXPECT_EQ(a.left_cm, expected.left_cm);
  EXPECT_EQ(a.right_cm, expected.right_cm);
  const arlequin::Inputs x = arlequin::encode_inputs(rm);
  EXPECT_GT(x[20] + x[21] + x[22] + x[23], 0.0) << "the neighbours' direction reaches the network";
}

TEST(ArlequinInControlSoftware, ANetworkIsWholeControlSoftware) {
  ControlSoftware software;
  software.architecture = Architecture::NeuralNetwork;
  software.network.weights = arlequin::shipped_weights(52);
  SwarmController controller(software, 2);
  SwarmState swarm = test::silent_swarm(2);
  swarm.light[1] = {0.1, 0.5, 0.2, 0, 0, 0, 0, 0};
  ReferenceModel rm;
  rm.update(swarm, 1);
  Rng rng(1), untouched(1);
  const Actuation a = controller.step(1, rm, rng);
  const Actuation expected = arlequin::drive(software.network.weights, rm);
  EXPECT_EQ(a.left_cm, expected.left_cm);
  EXPECT_EQ(a.right_cm, expected.right_cm);
  EXPECT_EQ(rng.next(), untouched.next());

  const Mission aac = load_mission("aac");
  Simulation simulation(aac, software);
  const double score = simulation.run(3);
  EXPECT_TRUE(std::isfinite(score));
  EXPECT_EQ(score, evaluate(aac, parse_control_software(to_config_string(software)), 3));
}

}  // namespace
}  // namespace sd
