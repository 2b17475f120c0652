// Malformed configuration strings are rejected with a ConfigError whose message names the
// offending token.
#include <gtest/gtest.h>

#include <string>

#include "control/config_string.hpp"
#include "control_test_helpers.hpp"

namespace sd {
namespace {

/// Parsing `text` must throw ConfigError naming `token`.
void expect_rejected(const std::string& text, const std::string& token) {
  SCOPED_TRACE(text);
  try {
    parse_control_software(text);
    ADD_FAILURE() << "accepted: " << text;
  } catch (const ConfigError& e) {
    EXPECT_TRUE(test::names_token(e.what(), token)) << "message does not name " << token << ": " << e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "threw something else than ConfigError: " << e.what();
  }
}

const std::string kTwoStops = "--fsm-config --nstates 2 --s0 11 --s1 11";
/// A two-state FSM with one transition 0 -> 1 whose condition part is `condition`.
std::string with_condition(const std::string& condition) { return kTwoStops + " --n0 1 --n0x0 0 " + condition; }

TEST(ControlGrammarErrors, UnknownBehaviourId) {
  expect_rejected("--fsm-config --nstates 1 --s0 16", "--s0");
  expect_rejected("--fsm-config --nstates 1 --s0 22", "--s0");  // TuttiFrutti has no 22
  expect_rejected("--fsm-config --nstates 1 --s0 6", "--s0");  // legacy 6 -> 16, unknown
  expect_rejected("--fsm-config --nstates 2 --s0 11 --s1 -1", "--s1");
  expect_rejected("--fsm-config --nstates 1 --s0 10.5 --rwm0 5", "--s0");
}

TEST(ControlGrammarErrors, UnknownConditionId) {
  expect_rejected(with_condition("--c0x0 16 --p0x0 0.5"), "--c0x0");
  expect_rejected(with_condition("--c0x0 9 --p0x0 0.5"), "--c0x0");
  expect_rejected(with_condition("--c0x0 17 --p0x0 0.5"), "--c0x0");
}

TEST(ControlGrammarErrors, MissingParameter) {
  expect_rejected("--fsm-config --nstates 1 --s0 10", "--rwm0");
  expect_rejected("--fsm-config --nstates 1 --s0 14", "--att0");
  expect_rejected("--fsm-config --nstates 1 --s0 15", "--rep0");
  expect_rejected(with_condition("--c0x0 15"), "--p0x0");
  expect_rejected(with_condition("--c0x0 13 --p0x0 3"), "--w0x0");
  expect_rejected(with_condition("--c0x0 14 --w0x0 3"), "--p0x0");
}

TEST(ControlGrammarErrors, MissingStructuralToken) {
  expect_rejected("--fsm-config --s0 11", "--nstates");
  expect_rejected("--fsm-config --nstates 2 --s0 11", "--s1");
  expect_rejected(kTwoStops + " --n0 1 --c0x0 15 --p0x0 0.5", "--n0x0");
  expect_rejected(kTwoStops + " --n0 1 --n0x0 0 --p0x0 0.5", "--c0x0");
  expect_rejected(kTwoStops + " --n0 2 --n0x0 0 --c0x0 15 --p0x0 0.5", "--n0x1");
}

TEST(ControlGrammarErrors, ParameterOutOfItsDomain) {
  expect_rejected("--fsm-config --nstates 1 --s0 14 --att0 6", "--att0");
  expect_rejected("--fsm-config --nstates 1 --s0 14 --att0 0.99", "--att0");
  expect_rejected("--fsm-config --nstates 1 --s0 15 --rep0 5.01", "--rep0");
  expect_rejected("--fsm-config --nstates 1 --s0 10 --rwm0 0", "--rwm0");
  expect_rejected("--fsm-config --nstates 1 --s0 10 --rwm0 101", "--rwm0");
  expect_rejected("--fsm-config --nstates 1 --s0 10 --rwm0 2.5", "--rwm0");  // integer parameter
  expect_rejected(with_condition("--c0x0 15 --p0x0 1.5"), "--p0x0");
  expect_rejected(with_condition("--c0x0 10 --p0x0 -0.1"), "--p0x0");
  expect_rejected(with_condition("--c0x0 13 --p0x0 11 --w0x0 1"), "--p0x0");   // xi 11
  expect_rejected(with_condition("--c0x0 14 --p0x0 0 --w0x0 1"), "--p0x0");    // xi 0
  expect_rejected(with_condition("--c0x0 13 --p0x0 2.5 --w0x0 1"), "--p0x0");  // xi integer
  expect_rejected(with_condition("--c0x0 13 --p0x0 5 --w0x0 20.5"), "--w0x0");
  expect_rejected(with_condition("--c0x0 14 --p0x0 5 --w0x0 -1"), "--w0x0");
}

TEST(ControlGrammarErrors, DestinationThatDoesNotExist) {
  // Three states: the other states of state 0 are indexed 0 and 1; k >= N - 1 = 2 is invalid.
  const std::string three = "--fsm-config --nstates 3 --s0 11 --s1 11 --s2 11 --n0 1 --c0x0 15 --p0x0 0.5 --n0x0 ";
  expect_rejected(three + "2", "--n0x0");
  expect_rejected(three + "3", "--n0x0");
  expect_rejected(three + "-1", "--n0x0");
  expect_rejected(three + "0.5", "--n0x0");
  expect_rejected(kTwoStops + " --n1 1 --n1x0 1 --c1x0 15 --p1x0 0.5", "--n1x0");
}

TEST(ControlGrammarErrors, TooManyOrTooFewStates) {
  expect_rejected("--fsm-config --nstates 5 --s0 11 --s1 11 --s2 11 --s3 11 --s4 11", "--nstates");
  expect_rejected("--fsm-config --nstates 0", "--nstates");
  expect_rejected("--fsm-config --nstates 2.5 --s0 11 --s1 11", "--nstates");
}

TEST(ControlGrammarErrors, TooManyTransitions) {
  std::string text = kTwoStops + " --n0 5";
  for (int j = 0; j < 5; ++j) {
    const std::string ij = "0x" + std::to_string(j);
    text += " --n" + ij + " 0 --c" + ij + " 15 --p" + ij + " 0.5";
  }
  expect_rejected(text, "--n0");
  expect_rejected(kTwoStops + " --n0 -1", "--n0");
}

TEST(ControlGrammarErrors, TransitionsOnASingleStateFsm) {
  expect_rejected("--fsm-config --nstates 1 --s0 11 --n0 1 --n0x0 0 --c0x0 15 --p0x0 0.5", "--n0");
}

TEST(ControlGrammarErrors, StrayTokens) {
  expect_rejected("--fsm-config --nstates 2 --s0 10 --rwm0 5 --s1 11 --rwm1 5", "--rwm1");  // Stop has no rwm
  expect_rejected(kTwoStops + " --s4 11", "--s4");                                        // no state 4
  expect_rejected("--fsm-config --nstates 1 --s0 10 --rwm0 5 --att0 2", "--att0");         // not Exploration's
  expect_rejected(with_condition("--c0x0 15 --p0x0 0.5 --w0x0 2"), "--w0x0");              // not FixedProb's
  expect_rejected(with_condition("--c0x0 15 --p0x0 0.5 --n0x1 0"), "--n0x1");              // beyond --n0 1
  expect_rejected(with_condition("--c0x0 15 --p0x0 0.5 --c0x1 15"), "--c0x1");
  expect_rejected(kTwoStops + " --n0x0 0", "--n0x0");                                     // no --n0
  expect_rejected(kTwoStops + " --foo0 1", "--foo0");
  expect_rejected(kTwoStops + " --s0y1 1", "--s0y1");
  expect_rejected(kTwoStops + " stray 1", "stray");
  expect_rejected("--fsm-config --nstates 1 --s0 11 --fsm-config 1", "--fsm-config");
}

TEST(ControlGrammarErrors, DuplicateToken) {
  expect_rejected("--fsm-config --nstates 1 --s0 10 --rwm0 5 --rwm0 6", "--rwm0");
  expect_rejected("--fsm-config --nstates 1 --nstates 1 --s0 11", "--nstates");
  expect_rejected("--fsm-config --nstates 1 --s0 11 --s0 11", "--s0");
}

TEST(ControlGrammarErrors, MissingValue) {
  expect_rejected("--fsm-config --nstates 1 --s0 10 --rwm0", "--rwm0");
  expect_rejected("--fsm-config --nstates --s0 11", "--nstates");
  expect_rejected("--fsm-config --nstates 1 --s0", "--s0");
}

TEST(ControlGrammarErrors, NonNumericValue) {
  expect_rejected("--fsm-config --nstates 1 --s0 10 --rwm0 abc", "--rwm0");
  expect_rejected("--fsm-config --nstates 1 --s0 10 --rwm0 5cm", "--rwm0");
  expect_rejected("--fsm-config --nstates one --s0 11", "--nstates");
  expect_rejected("--fsm-config --nstates 1 --s0 Stop", "--s0");
  expect_rejected(with_condition("--c0x0 15 --p0x0 nan"), "--p0x0");
  expect_rejected(with_condition("--c0x0 15 --p0x0 inf"), "--p0x0");
}

TEST(ControlGrammarErrors, EmptyOrWhitespaceString) {
  for (const std::string text : {"", "   ", "\t\n"}) {
    EXPECT_THROW(parse_control_software(text), ConfigError) << "'" << text << "'";
    EXPECT_THROW(parse_control_software(split_tokens(text)), ConfigError);
  }
  EXPECT_THROW(parse_control_software("--fsm-config"), ConfigError);
}

TEST(ControlGrammarErrors, MalformedBehaviourTrees) {
  const std::string maple = "--bt-config --nroot 3 --nchildroot 1 --n0 0 --nchild0 2 --n00 6 --c00 15 --p00 0.5 ";
  expect_rejected(maple + "--n01 5 --a01 11 --p01 0 --rwm01 4", "--rwm01");  // Stop has no rwm
  expect_rejected(maple + "--n01 7 --a01 11", "--n01");                     // no node type 7
  expect_rejected(maple + "--n01 5", "--a01");                               // action without behaviour
  expect_rejected(maple + "--n01 5 --a01 11 --p01 1.5", "--p01");            // success probability
  expect_rejected(maple + "--n01 4 --nchild01 2 --n010 6 --c010 15 --p010 1 --n011 6 --c011 15 --p011 1",
                  "--nchild01");                                           // a negation has one child
  expect_rejected("--bt-config --nroot 3 --nchildroot 1 --n0 0 --nchild0 1", "--n00");
  expect_rejected("--bt-config --nroot 9 --nchildroot 1", "--nroot");
  expect_rejected("--bt-config --nroot 3 --nchildroot 1 --n0 4 --nchild0 1 --n00 4 --nchild00 1 --n000 4 --nchild000 1 "
                  "--n0000 4 --nchild0000 1 --n00000 4 --nchild00000 1 --n000000 5 --a000000 11",
                  "000000");                                               // deeper than 5 levels
}

TEST(ControlGrammarErrors, UnknownLeadingToken) { expect_rejected("--foo-config --nstates 1 --s0 11", "--foo-config"); }

}  // namespace
}  // namespace sd
