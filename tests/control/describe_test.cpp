// Human-readable views list modules with their parameters and transitions by absolute target.
#include <gtest/gtest.h>

#include <string>

#include "control/config_string.hpp"
#include "control/describe.hpp"

namespace sd {
namespace {

TEST(ControlDescribe, ListingNamesModulesAndAbsoluteTargets) {
  const ControlSoftware software = parse_control_software(
      "--fsm-config --nstates 3 --s0 14 --att0 3.5 --n0 1 --n0x0 1 --c0x0 13 --p0x0 5 --w0x0 2 --s1 11 --s2 10 --rwm2 7");
  const std::string text = describe(software);
  EXPECT_NE(text.find("3 state(s)"), std::string::npos) << text;
  EXPECT_NE(text.find("state 0: Attraction[14](att=3.5)"), std::string::npos) << text;
  EXPECT_NE(text.find("-> state 2 when NeighborsCount[13](p=5, w=2)"), std::string::npos) << text;
  EXPECT_NE(text.find("state 2: Exploration[10](rwm=7)"), std::string::npos) << text;
  EXPECT_NE(text.find("state 1: Stop[11]\n"), std::string::npos) << text;
}

TEST(ControlDescribe, DotHasOneNodePerStateAndOneEdgePerTransition) {
  const ControlSoftware software = parse_control_software(
      "--fsm-config --nstates 2 --s0 11 --n0 1 --n0x0 0 --c0x0 15 --p0x0 0.5 --s1 12 --n1 1 --n1x0 0 --c1x0 10 --p1x0 1");
  const std::string dot = to_dot(software);
  EXPECT_NE(dot.find("s0 -> s1"), std::string::npos) << dot;
  EXPECT_NE(dot.find("s1 -> s0"), std::string::npos) << dot;
  EXPECT_NE(dot.find("peripheries=2"), std::string::npos) << dot;  // the initial state
  EXPECT_EQ(dot.find("s0 -> s0"), std::string::npos) << dot;
}

TEST(ControlDescribe, UnknownModuleIsShownByItsId) {
  ModuleInstance m;
  m.id = 77;
  EXPECT_EQ(describe_module(m, ModuleKind::Behaviour), "unknown(77)");
}

}  // namespace
}  // namespace sd
