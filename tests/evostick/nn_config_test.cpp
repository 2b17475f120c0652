// The --nn-config grammar of EvoStick networks: all 50 weights --w<o>x<i>, printed with the
// shortest text that reads back as the same double, errors that name the token.
#include <gtest/gtest.h>

#include "control/config_string.hpp"
#include "control/describe.hpp"
#include "core/rng.hpp"

namespace sd {
namespace {

ControlSoftware random_network(std::uint64_t seed) {
  Rng rng(seed);
  ControlSoftware s;
  s.architecture = Architecture::NeuralNetwork;
  for (double& w : s.network.weights) w = rng.uniform(-5.0, 5.0);
  return s;
}

std::string error_of(const std::string& text) {
  try {
    parse_control_software(text);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "no error";
}

TEST(NnConfig, PrintThenParseGivesTheSameWeightsBitForBit) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const ControlSoftware s = random_network(seed);
    const std::string text = to_config_string(s);
    EXPECT_EQ(text.rfind("--nn-config --w0x0 ", 0), 0u);
    const ControlSoftware back = parse_control_software(text);
    EXPECT_EQ(back, s);
    EXPECT_EQ(to_config_string(back), text);
  }
}

TEST(NnConfig, TokensNameOutputThenInputInAnyOrder) {
  std::string text = "--nn-config";
  for (int i = 24; i >= 0; --i)
    for (int o = 1; o >= 0; --o) text += " --w" + std::to_string(o) + "x" + std::to_string(i) + " " + std::to_string(o * 100 + i);
  const ControlSoftware s = parse_control_software(text);
  EXPECT_EQ(s.architecture, Architecture::NeuralNetwork);
  EXPECT_EQ(s.network.weights[0], 0.0);    // left, input 0
  EXPECT_EQ(s.network.weights[24], 24.0);  // left bias
  EXPECT_EQ(s.network.weights[25], 100.0); // right, input 0
  EXPECT_EQ(s.network.weights[49], 124.0); // right bias
}

TEST(NnConfig, MalformedStringsNameTheOffendingToken) {
  const std::string full = to_config_string(random_network(3));
  const std::string without_last = full.substr(0, full.rfind(" --w1x24"));
  EXPECT_EQ(error_of(without_last), "missing --w1x24 (a network needs all 50 weights)");
  EXPECT_NE(error_of(full + " --w2x0 1").find("unexpected token '--w2x0 1'"), std::string::npos);
  EXPECT_NE(error_of(full + " --w0x25 1").find("'--w0x25 1'"), std::string::npos);
  EXPECT_NE(error_of(full + " --w0x3 1").find("duplicate token '--w0x3'"), std::string::npos);
  EXPECT_NE(error_of("--nn-config --w0x0 abc").find("'--w0x0 abc': the value is not a number"), std::string::npos);
  EXPECT_NE(error_of("--nn-config --w0x0 nan").find("not a number"), std::string::npos);
  EXPECT_NE(error_of("--nn-config --nstates 1").find("'--nstates"), std::string::npos);
  EXPECT_NE(error_of("--nnconfig").find("--nn-config"), std::string::npos);
}

TEST(NnConfig, ReadsEveryNetworkInputAndDescribesItself) {
  const ControlSoftware s = random_network(5);
  EXPECT_EQ(s.inputs(), kProximityInput | kLightInput | kGroundInput | kRangeAndBearingInput);
  const std::string text = describe(s);
  EXPECT_NE(text.find("25 inputs -> 2 sigmoid outputs"), std::string::npos);
  EXPECT_NE(text.find(format_number(s.network.weights[49])), std::string::npos);
  EXPECT_NE(to_dot(s).find("digraph nn"), std::string::npos);
}

}  // namespace
}  // namespace sd
