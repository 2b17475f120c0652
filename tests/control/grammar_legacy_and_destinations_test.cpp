// Legacy one-digit Chocolate strings and the "index among the other states" destination
// encoding of --n<i>x<j> (as ARGoS3-AutoMoDe's FSM builder reads it).
#include <gtest/gtest.h>

#include <string>

#include "control/config_string.hpp"
#include "control_test_helpers.hpp"

namespace sd {
namespace {

using test::fsm;
using test::module;
using test::state;
using test::transition;

TEST(ControlGrammarLegacy, OneDigitExplorationIsChocolateExploration) {
  const ControlSoftware legacy = parse_control_software("--nstates 1 --s0 0 --rwm0 50");
  const ControlSoftware current = parse_control_software("--nstates 1 --s0 10 --rwm0 50");
  EXPECT_EQ(legacy, current);
  EXPECT_EQ(legacy, fsm({state(module(10, {50}))}));
  EXPECT_EQ(parse_control_software("--fsm-config --nstates 1 --s0 0 --rwm0 50"), current);
}

TEST(ControlGrammarLegacy, EveryOneDigitBehaviourMapsToTenPlusDigit) {
  const std::string params[] = {" --rwm0 5", "", "", "", " --att0 2", " --rep0 3"};
  for (int digit = 0; digit < 6; ++digit) {
    const std::string tail = params[digit];
    const ControlSoftware legacy = parse_control_software("--nstates 1 --s0 " + std::to_string(digit) + tail);
    const ControlSoftware current = parse_control_software("--nstates 1 --s0 " + std::to_string(10 + digit) + tail);
    EXPECT_EQ(legacy, current) << "digit " << digit;
    EXPECT_EQ(legacy.fsm.states[0].behaviour.id, 10 + digit);
  }
}

TEST(ControlGrammarLegacy, EveryOneDigitConditionMapsToTenPlusDigit) {
  const std::string params[] = {" --p0x0 0.5", " --p0x0 0.5", " --p0x0 0.5", " --p0x0 3 --w0x0 2.5",
                                " --p0x0 3 --w0x0 2.5", " --p0x0 0.5"};
  for (int digit = 0; digit < 6; ++digit) {
    const std::string legacy_text =
        "--nstates 2 --s0 1 --n0 1 --n0x0 0 --c0x0 " + std::to_string(digit) + params[digit] + " --s1 1";
    const std::string current_text =
        "--nstates 2 --s0 11 --n0 1 --n0x0 0 --c0x0 " + std::to_string(10 + digit) + params[digit] + " --s1 11";
    const ControlSoftware legacy = parse_control_software(legacy_text);
    EXPECT_EQ(legacy, parse_control_software(current_text)) << legacy_text;
    EXPECT_EQ(legacy.fsm.states[0].transitions[0].condition.id, 10 + digit);
  }
}

TEST(ControlGrammarLegacy, SpecExampleReadsAsChocolateAndPrintsTwoDigitIds) {
  const ControlSoftware legacy = parse_control_software(
      "--nstates 2 --s0 4 --att0 3.25 --n0 1 --n0x0 0 --c0x0 3 --p0x0 5 --w0x0 10.2 "
      "--s1 0 --rwm1 50 --n1 1 --n1x0 0 --c1x0 5 --p1x0 0.5");
  const ControlSoftware expected = fsm({state(module(14, {3.25}), {transition(1, module(13, {5, 10.2}))}),
                                        state(module(10, {50}), {transition(0, module(15, {0.5}))})});
  EXPECT_EQ(legacy, expected);
  EXPECT_EQ(to_config_string(legacy),
            "--fsm-config --nstates 2 --s0 14 --att0 3.25 --n0 1 --n0x0 0 --c0x0 13 --p0x0 5 --w0x0 10.2 "
            "--s1 10 --rwm1 50 --n1 1 --n1x0 0 --c1x0 15 --p1x0 0.5");
}

TEST(ControlGrammarLegacy, MixingOneAndTwoDigitIdsIsRejected) {
  // Either every id has one digit (legacy) or none has: a lone 0 among two-digit ids is an
  // unknown behaviour, reported on its token.
  try {
    parse_control_software("--nstates 2 --s0 0 --rwm0 5 --s1 11");
    FAIL() << "mixed ids accepted";
  } catch (const ConfigError& e) {
    EXPECT_TRUE(test::names_token(e.what(), "--s0")) << e.what();
  }
}

TEST(ControlGrammarDestinations, ThreeStatesFromTheMiddleState) {
  const std::string head = "--nstates 3 --s0 11 --s1 11 --s2 11 --n1 1 --c1x0 15 --p1x0 1 --n1x0 ";
  EXPECT_EQ(parse_control_software(head + "0").fsm.states[1].transitions[0].target, 0);
  EXPECT_EQ(parse_control_software(head + "1").fsm.states[1].transitions[0].target, 2);
}

TEST(ControlGrammarDestinations, EveryOriginAndIndexOfAFourStateFsm) {
  for (int origin = 0; origin < 4; ++origin) {
    for (int k = 0; k < 3; ++k) {
      std::string text = "--nstates 4 --s0 11 --s1 11 --s2 11 --s3 11";
      const std::string o = std::to_string(origin);
      text += " --n" + o + " 1 --n" + o + "x0 " + std::to_string(k) + " --c" + o + "x0 15 --p" + o + "x0 0.5";
      const ControlSoftware software = parse_control_software(text);
      const int expected = k < origin ? k : k + 1;  // the k-th of the other states
      EXPECT_EQ(software.fsm.states[static_cast<std::size_t>(origin)].transitions[0].target, expected) << text;
      // And printing writes the index among the other states back.
      EXPECT_NE(to_config_string(software).find(" --n" + o + "x0 " + std::to_string(k) + " "), std::string::npos)
          << to_config_string(software);
    }
  }
}

TEST(ControlGrammarDestinations, PrinterEncodesAbsoluteTargetsRelatively) {
  const ControlSoftware software =
      fsm({state(module(11), {transition(2, module(15, {0.5}))}), state(module(11)),
           state(module(11), {transition(0, module(15, {0.5})), transition(1, module(15, {0.25}))})});
  const std::string text = to_config_string(software);
  EXPECT_NE(text.find("--n0x0 1 "), std::string::npos) << text;  // 2 from 0: second other state
  EXPECT_NE(text.find("--n2x0 0 "), std::string::npos) << text;
  EXPECT_NE(text.find("--n2x1 1 "), std::string::npos) << text;
}

}  // namespace
}  // namespace sd
