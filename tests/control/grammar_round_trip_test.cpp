// Printing then parsing any valid control software gives it back bit for bit, and parsing
// then printing then parsing is stable.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include "control/config_string.hpp"
#include "control_test_helpers.hpp"
#include "core/rng.hpp"
#include "test_paths.hpp"

namespace sd {
namespace {

using test::fsm;
using test::module;
using test::state;
using test::transition;

/// Equality of every parameter down to the bit (so -0.0 != 0.0 and NaN payloads count).
void expect_bit_identical(const ControlSoftware& a, const ControlSoftware& b) {
  ASSERT_EQ(a.architecture, b.architecture);
  ASSERT_EQ(a.fsm.states.size(), b.fsm.states.size());
  auto same_module = [](const ModuleInstance& x, const ModuleInstance& y) {
    EXPECT_EQ(x.id, y.id);
    for (std::size_t p = 0; p < x.parameters.size(); ++p)
      EXPECT_EQ(std::bit_cast<std::uint64_t>(x.parameters[p]), std::bit_cast<std::uint64_t>(y.parameters[p]))
          << "parameter " << p << ": " << x.parameters[p] << " vs " << y.parameters[p];
  };
  for (std::size_t i = 0; i < a.fsm.states.size(); ++i) {
    const FsmState& sa = a.fsm.states[i];
    const FsmState& sb = b.fsm.states[i];
    same_module(sa.behaviour, sb.behaviour);
    ASSERT_EQ(sa.transitions.size(), sb.transitions.size()) << "state " << i;
    for (std::size_t j = 0; j < sa.transitions.size(); ++j) {
      EXPECT_EQ(sa.transitions[j].target, sb.transitions[j].target) << "state " << i << " transition " << j;
      same_module(sa.transitions[j].condition, sb.transitions[j].condition);
    }
  }
}

void expect_print_parse_print(const ControlSoftware& software) {
  const std::string printed = to_config_string(software);
  SCOPED_TRACE(printed);
  const ControlSoftware parsed = parse_control_software(printed);
  expect_bit_identical(software, parsed);
  EXPECT_EQ(to_config_string(parsed), printed);
}

void expect_parse_print_parse(const std::string& text) {
  SCOPED_TRACE(text);
  const ControlSoftware first = parse_control_software(text);
  const std::string printed = to_config_string(first);
  const ControlSoftware second = parse_control_software(printed);
  expect_bit_identical(first, second);
  EXPECT_EQ(to_config_string(second), printed);
}

TEST(ControlGrammarRoundTrip, EveryChocolateBehaviourAlone) {
  expect_print_parse_print(fsm({state(module(10, {50}))}));
  expect_print_parse_print(fsm({state(module(11))}));
  expect_print_parse_print(fsm({state(module(12))}));
  expect_print_parse_print(fsm({state(module(13))}));
  expect_print_parse_print(fsm({state(module(14, {3.25}))}));
  expect_print_parse_print(fsm({state(module(15, {1.5}))}));
}

TEST(ControlGrammarRoundTrip, EveryChocolateConditionOnATransition) {
  const std::vector<ModuleInstance> conditions = {module(10, {0.3}), module(11, {0.7}),      module(12, {1}),
                                                  module(13, {5, 10.2}), module(14, {1, 0}), module(15, {0.5})};
  for (const ModuleInstance& c : conditions)
    expect_print_parse_print(fsm({state(module(11), {transition(1, c)}), state(module(12), {transition(0, c)})}));
}

TEST(ControlGrammarRoundTrip, ParametersAtTheEdgesOfTheirDomains) {
  // rwm integer [1,100]; att, rep real [1,5]; p real [0,1]; xi integer [1,10]; eta real [0,20].
  const double below_one = std::nextafter(1.0, 0.0);
  const double above_one = std::nextafter(1.0, 2.0);
  const double below_five = std::nextafter(5.0, 0.0);
  const double denormal = std::numeric_limits<double>::denorm_min();
  expect_print_parse_print(fsm({state(module(10, {1}))}));
  expect_print_parse_print(fsm({state(module(10, {100}))}));
  for (const double a : {1.0, above_one, 3.999999, below_five, 5.0}) {
    expect_print_parse_print(fsm({state(module(14, {a}))}));
    expect_print_parse_print(fsm({state(module(15, {a}))}));
  }
  for (const double p : {0.0, denormal, 1e-7, 0.1, 1.0 / 3.0, below_one, 1.0}) {
    for (const int id : {10, 11, 12, 15})
      expect_print_parse_print(fsm({state(module(11), {transition(1, module(id, {p}))}), state(module(11))}));
  }
  for (const double xi : {1.0, 10.0})
    for (const double eta : {0.0, denormal, 1e-7, 0.1, std::nextafter(20.0, 0.0), 20.0})
      for (const int id : {13, 14})
        expect_print_parse_print(fsm({state(module(11), {transition(1, module(id, {xi, eta}))}), state(module(11))}));
}

TEST(ControlGrammarRoundTrip, NegativeZeroProbabilityKeepsItsSign) {
  // -0 is inside [0, 1]; the printed text must carry the sign so the bits survive.
  expect_print_parse_print(fsm({state(module(11), {transition(1, module(15, {-0.0}))}), state(module(11))}));
}

TEST(ControlGrammarRoundTrip, FourStatesWithFourTransitionsEach) {
  std::vector<FsmState> states;
  for (int i = 0; i < 4; ++i) {
    FsmState s = state(i == 0 ? module(10, {7}) : module(10 + i));
    for (int j = 0; j < 4; ++j) {
      const int target = (i + 1 + j % 3) % 4;  // never i
      s.transitions.push_back(transition(target, module(10 + (i + j) % 6, {0.25 * j})));
      if (s.transitions.back().condition.id == 13 || s.transitions.back().condition.id == 14)
        s.transitions.back().condition.parameters = {static_cast<double>(j + 1), 0.5 + j, 0, 0};
    }
    states.push_back(s);
  }
  ControlSoftware software;
  software.fsm.states = states;
  expect_print_parse_print(software);
}

TEST(ControlGrammarRoundTrip, ParsePrintParseOfHandWrittenStrings) {
  const std::vector<std::string> texts = {
      "--fsm-config --nstates 1 --s0 10 --rwm0 50",
      "--fsm-config --nstates 1 --s0 11",
      "--fsm-config --nstates 2 --s0 14 --att0 3.25 --n0 1 --n0x0 0 --c0x0 13 --p0x0 5 --w0x0 10.2 "
      "--s1 10 --rwm1 50 --n1 1 --n1x0 0 --c1x0 15 --p1x0 0.5",
      // Tokens in another order, a redundant "--n0 0" and values written unusually.
      "--fsm-config --nstates 2 --s1 11 --s0 12 --n0 1 --p0x0 1.0e-1 --c0x0 12 --n0x0 0 --n1 0",
      "--nstates 3 --s0 15 --rep0 4.99 --s1 13 --s2 12 --n2 2 --n2x0 1 --c2x0 14 --p2x0 10 --w2x0 0 "
      "--n2x1 0 --c2x1 10 --p2x1 0.000001",
  };
  for (const std::string& text : texts) expect_parse_print_parse(text);
}

TEST(ControlGrammarRoundTrip, PrintedNumbersAreTheShortestExactText) {
  EXPECT_EQ(format_number(0.1), "0.1");
  EXPECT_EQ(format_number(50.0), "50");
  EXPECT_EQ(std::stod(format_number(3.999999)), 3.999999);
  EXPECT_EQ(std::stod(format_number(1e-7)), 1e-7);
  const double third = 1.0 / 3.0;
  EXPECT_EQ(std::stod(format_number(third)), third);
}

/// A random valid FSM: any Chocolate module, any parameter value of its domain, with
/// uniformly random doubles (all 53 bits used) for real parameters.
ControlSoftware random_fsm(Rng& rng) {
  auto real_in = [&](double lo, double hi) { return std::min(hi, lo + (hi - lo) * rng.uniform()); };
  auto integer_in = [&](int lo, int hi) { return static_cast<double>(lo + static_cast<int>(rng.below(static_cast<std::uint32_t>(hi - lo + 1)))); };
  ControlSoftware software;
  const int n = 1 + static_cast<int>(rng.below(4));
  for (int i = 0; i < n; ++i) {
    FsmState s;
    s.behaviour.id = 10 + static_cast<int>(rng.below(6));
    if (s.behaviour.id == 10) s.behaviour.parameters[0] = integer_in(1, 100);
    if (s.behaviour.id == 14 || s.behaviour.id == 15) s.behaviour.parameters[0] = real_in(1, 5);
    const int transitions = n == 1 ? 0 : static_cast<int>(rng.below(5));
    for (int j = 0; j < transitions; ++j) {
      FsmTransition t;
      t.target = static_cast<int>(rng.below(static_cast<std::uint32_t>(n - 1)));
      if (t.target >= i) ++t.target;
      t.condition.id = 10 + static_cast<int>(rng.below(6));
      if (t.condition.id == 13 || t.condition.id == 14) {
        t.condition.parameters[0] = integer_in(1, 10);
        t.condition.parameters[1] = real_in(0, 20);
      } else {
        t.condition.parameters[0] = real_in(0, 1);
      }
      s.transitions.push_back(t);
    }
    software.fsm.states.push_back(s);
  }
  return software;
}

TEST(ControlGrammarRoundTrip, RandomFsmsRoundTripBitExactly) {
  Rng rng(20240917);
  for (int trial = 0; trial < 400; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const ControlSoftware software = random_fsm(rng);
    expect_print_parse_print(software);
    expect_parse_print_parse(to_config_string(software));
    if (testing::Test::HasFailure()) break;
  }
}

// The five controllers whose ARGoS scores are in tests/data/argos-reference.csv.
const std::vector<std::string>& calibration_controllers() {
  static const std::vector<std::string> texts = {
      "--fsm-config --nstates 1 --s0 10 --rwm0 50",
      "--fsm-config --nstates 2 --s0 14 --att0 5 --n0 1 --n0x0 0 --c0x0 10 --p0x0 1.0 --s1 11 --n1 1 --n1x0 0 "
      "--c1x0 11 --p1x0 0.1",
      "--fsm-config --nstates 2 --s0 10 --rwm0 50 --n0 1 --n0x0 0 --c0x0 10 --p0x0 1 --s1 12 --n1 1 --n1x0 0 "
      "--c1x0 12 --p1x0 1",
      "--fsm-config --nstates 2 --s0 10 --rwm0 4 --n0 1 --n0x0 0 --c0x0 10 --p0x0 0.57 --s1 12 --n1 1 --n1x0 0 "
      "--c1x0 12 --p1x0 0.57",
      "--fsm-config --nstates 4 --s0 11 --n0 1 --n0x0 2 --c0x0 11 --p0x0 0.87 --s1 11 --n1 3 --n1x0 2 --c1x0 10 "
      "--p1x0 0.7 --n1x1 0 --c1x1 11 --p1x1 0.01 --n1x2 2 --c1x2 14 --p1x2 8 --w1x2 5.07 --s2 14 --att2 1.38 "
      "--n2 1 --n2x0 2 --c2x0 15 --p2x0 0.66 --s3 10 --rwm3 24 --n3 4 --n3x0 0 --c3x0 13 --p3x0 5 --w3x0 3.61 "
      "--n3x1 2 --c3x1 11 --p3x1 0.63 --n3x2 1 --c3x2 12 --p3x2 0.51 --n3x3 1 --c3x3 12 --p3x3 0.41",
  };
  return texts;
}

TEST(ControlGrammarCalibration, PublishedControllersParseAndRoundTrip) {
  for (const std::string& text : calibration_controllers()) expect_parse_print_parse(text);
}

TEST(ControlGrammarCalibration, LargestPublishedControllerHasTheExpectedStructure) {
  const ControlSoftware f5 = parse_control_software(calibration_controllers()[4]);
  ASSERT_EQ(f5.fsm.states.size(), 4u);
  const auto& s = f5.fsm.states;
  EXPECT_EQ(s[0].behaviour, module(11));
  ASSERT_EQ(s[0].transitions.size(), 1u);
  EXPECT_EQ(s[0].transitions[0].target, 3);  // k = 2 from state 0 -> state 3
  EXPECT_EQ(s[0].transitions[0].condition, module(11, {0.87}));
  ASSERT_EQ(s[1].transitions.size(), 3u);
  EXPECT_EQ(s[1].transitions[0].target, 3);  // k = 2 >= 1 -> 3
  EXPECT_EQ(s[1].transitions[1].target, 0);  // k = 0 < 1 -> 0
  EXPECT_EQ(s[1].transitions[2].condition, module(14, {8, 5.07}));
  EXPECT_EQ(s[2].behaviour, module(14, {1.38}));
  EXPECT_EQ(s[2].transitions[0].target, 3);  // k = 2 >= 2 -> 3
  EXPECT_EQ(s[3].behaviour, module(10, {24}));
  ASSERT_EQ(s[3].transitions.size(), 4u);
  EXPECT_EQ(s[3].transitions[0].target, 0);
  EXPECT_EQ(s[3].transitions[0].condition, module(13, {5, 3.61}));
  EXPECT_EQ(s[3].transitions[1].target, 2);
  EXPECT_EQ(s[3].transitions[2].target, 1);
  EXPECT_EQ(s[3].transitions[3].target, 1);
}

std::vector<std::string> split_csv_line(const std::string& line) {
  std::vector<std::string> fields(1);
  for (const char ch : line) {
    if (ch == ',') fields.emplace_back();
    else if (ch != '\r') fields.back() += ch;
  }
  return fields;
}

TEST(ControlGrammarCalibration, EveryRowOfTheSharedCalibrationFileParses) {
  // The repository's copy of the ARGoS calibration table: it is always there, so a missing
  // file is a failure, never a skip.
  const std::string path = std::string(::sd::test::source_dir()) + "/tests/data/argos-reference.csv";
  std::ifstream in(path);
  ASSERT_TRUE(in) << "cannot read " << path;
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  const auto header = split_csv_line(line);
  ASSERT_GE(header.size(), 3u);
  ASSERT_EQ(header[2], "config");
  int rows = 0;
  while (std::getline(in, line)) {
    if (line.empty()) continue;
    const auto fields = split_csv_line(line);
    ASSERT_GE(fields.size(), 3u) << line;
    SCOPED_TRACE(fields[2]);
    EXPECT_NO_THROW(expect_parse_print_parse(fields[2]));
    ++rows;
  }
  EXPECT_GT(rows, 0);
}

}  // namespace
}  // namespace sd
