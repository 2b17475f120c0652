#include <gtest/gtest.h>

#include <stdexcept>

#include "design/fsm_space.hpp"
#include "design/parameter_space.hpp"

using namespace sd::design;

namespace {

const ParameterSpace& chocolate() {
  static const ParameterSpace space = build_fsm_space(chocolate_fsm_modules());
  return space;
}

// Two states: Attraction, left on NeighborsCount; Exploration, left with probability 0.5.
const char* kExample =
    "--fsm-config --nstates 2 --s0 14 --att0 3.25 --n0 1 --n0x0 0 --c0x0 13 --p0x0 5 --w0x0 10.2 "
    "--s1 10 --rwm1 50 --n1 1 --n1x0 0 --c1x0 15 --p1x0 0.5";

}  // namespace

TEST(design_FsmSpace, ChocolateHasTheGrammarStructure) {
  const ParameterSpace& s = chocolate();
  // ARCH (fixed) + NumStates + 4 x (S, RWM, ATT, REP, NumConnections) + 16 x (N, C, P, B, W)
  EXPECT_EQ(s.size(), 102u);
  EXPECT_EQ(s.nb_variable(), 101u);
  EXPECT_TRUE(s[*s.index_of("ARCH")].is_fixed());
  const Parameter& n = s[*s.index_of("N2x3")];
  EXPECT_TRUE(n.is_dependent());
  EXPECT_EQ(n.switch_, "--n2x3 ");
  // ξ travels in --p<i>x<j>, η in --w<i>x<j> (AutoMoDe master encoding).
  EXPECT_EQ(s[*s.index_of("B1x2")].switch_, "--p1x2 ");
  EXPECT_EQ(s[*s.index_of("W1x2")].switch_, "--w1x2 ");
  EXPECT_EQ(s[*s.index_of("S3")].values, (std::vector<std::string>{"10", "11", "12", "13", "14", "15"}));
  // Sampling order puts every parameter after what its condition and domain read.
  std::vector<std::size_t> rank(s.size());
  for (std::size_t k = 0; k < s.size(); ++k) rank[s.sampling_order()[k]] = k;
  EXPECT_LT(rank[*s.index_of("NumStates")], rank[*s.index_of("N0x0")]);
  EXPECT_LT(rank[*s.index_of("NumConnections0")], rank[*s.index_of("N0x0")]);
  EXPECT_LT(rank[*s.index_of("C0x0")], rank[*s.index_of("P0x0")]);
}

TEST(design_FsmSpace, ParsesAndRendersTheSpecExample) {
  const ParameterSpace& s = chocolate();
  const Configuration c = s.parse(kExample);
  EXPECT_EQ(s.validate(c), "");
  EXPECT_EQ(s.render(c), kExample);
  EXPECT_EQ(c.values[*s.index_of("NumStates")], 2);
  EXPECT_EQ(s.value_text(c, *s.index_of("S0")), "14");
  EXPECT_EQ(c.values[*s.index_of("B0x0")], 5);   // ξ of NeighborsCount
  EXPECT_TRUE(is_na(c.values[*s.index_of("P0x0")]));  // shares --p0x0 but inactive for condition 13
  EXPECT_EQ(c.values[*s.index_of("P1x0")], 0.5);
  EXPECT_TRUE(is_na(c.values[*s.index_of("S2")]));
  // Token order does not matter for reading.
  const Configuration shuffled = s.parse(
      "--s1 10 --nstates 2 --fsm-config --rwm1 50 --n1 1 --n1x0 0 --c1x0 15 --p1x0 0.5 --s0 14 --att0 3.25 --n0 1 "
      "--n0x0 0 --c0x0 13 --w0x0 10.2 --p0x0 5");
  EXPECT_EQ(shuffled, c);
}

TEST(design_FsmSpace, RejectsMalformedStringsNamingTheToken) {
  const ParameterSpace& s = chocolate();
  auto message = [&](const std::string& text) {
    try {
      s.parse(text);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  // Transition target must be within 0..NumStates-2 (dependent domain).
  EXPECT_NE(message("--fsm-config --nstates 2 --s0 11 --n0 1 --n0x0 1 --c0x0 15 --p0x0 0.5 --s1 11 --n1 1 --n1x0 0 "
                    "--c1x0 15 --p1x0 0.5")
                .find("--n0x0"),
            std::string::npos);
  EXPECT_NE(message("--fsm-config --nstates 1 --s0 11 --bogus 3").find("--bogus"), std::string::npos);
  EXPECT_NE(message("--fsm-config --nstates 1 --s0 16").find("--s0"), std::string::npos);
  EXPECT_NE(message("--fsm-config --nstates 1 --s0 10").find("RWM0"), std::string::npos);       // missing
  EXPECT_NE(message("--fsm-config --nstates 1 --s0 11 --rwm0 5").find("--rwm0"), std::string::npos);  // superfluous
  EXPECT_NE(message("--fsm-config --nstates 1 --s0 10 --rwm0 5.5").find("integer"), std::string::npos);
  EXPECT_NE(message("--fsm-config --nstates 1 --s0 11 --s0 12").find("repeated"), std::string::npos);
}

TEST(design_ParameterSpace, ConditionsAndDependentDomains) {
  ParameterSpace s(2);
  s.add({"A", "--a ", ParamType::Categorical, {"x", "y", "z"}, {}, {}, false, {}});
  s.add({"N", "--n ", ParamType::Integer, {}, Bound::fixed(1), Bound::fixed(4), false, {}});
  s.add({"R", "--r ", ParamType::Real, {}, Bound::fixed(0), Bound::fixed(10), false,
         {{"A", Clause::Op::In, {"x", "y"}, 0}}});
  s.add({"D", "--d ", ParamType::Integer, {}, Bound::fixed(0), Bound::of("N", -2), false,
         {{"N", Clause::Op::Gt, {}, 1}}});
  s.add({"G", "--g=", ParamType::Ordinal, {"lo", "hi"}, {}, {}, false,
         {{"A", Clause::Op::NotIn, {"x"}, 0}, {"N", Clause::Op::Le, {}, 3}}});
  s.finalize();
  const Configuration c = s.parse("--a y --n 3 --r 2.5 --d 1 --g=hi");
  EXPECT_EQ(s.render(c), "--a y --n 3 --r 2.5 --d 1 --g=hi");
  const auto dom = s.domain(c, *s.index_of("D"));
  ASSERT_TRUE(dom);
  EXPECT_EQ(dom->second, 1);
  EXPECT_THROW(s.parse("--a z --n 4 --d 1 --g=hi"), std::invalid_argument);  // G inactive for N = 4
  EXPECT_EQ(s.render(s.parse("--a z --n 4 --d 2")), "--a z --n 4 --d 2");
  // Reals keep `digits` decimals; rendering drops trailing zeros.
  EXPECT_EQ(s.value_text(s.parse("--a x --n 1 --r 2.50"), *s.index_of("R")), "2.5");
  EXPECT_EQ(s.round_real(3.14159), 3.14);
}

TEST(design_ParameterSpace, RejectsCyclesAndUnknownNames) {
  ParameterSpace cyc;
  cyc.add({"A", "--a ", ParamType::Integer, {}, Bound::fixed(0), Bound::fixed(3), false, {{"B", Clause::Op::Gt, {}, 0}}});
  cyc.add({"B", "--b ", ParamType::Integer, {}, Bound::fixed(0), Bound::fixed(3), false, {{"A", Clause::Op::Gt, {}, 0}}});
  EXPECT_THROW(cyc.finalize(), std::invalid_argument);
  ParameterSpace unknown;
  unknown.add({"A", "--a ", ParamType::Integer, {}, Bound::fixed(0), Bound::of("Z", 0), false, {}});
  EXPECT_THROW(unknown.finalize(), std::invalid_argument);
  ParameterSpace dup;
  dup.add({"A", "--a ", ParamType::Categorical, {"1"}, {}, {}, false, {}});
  EXPECT_THROW(dup.add({"A", "--b ", ParamType::Categorical, {"1"}, {}, {}, false, {}}), std::invalid_argument);
}
