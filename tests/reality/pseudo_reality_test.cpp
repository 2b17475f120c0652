// The pseudo-reality specification: what each law draws, that sample k is a pure function of
// (knobs, k, design model), and that every malformed specification is refused in one line
// naming the field.
#include <gtest/gtest.h>

#include <set>

#include "reality/pseudo_reality.hpp"

namespace sd {
namespace {

PseudoRealitySpec parse(const std::string& text) { return parse_pseudo_reality(text, "spec.json"); }

std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const PseudoRealityError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(PseudoReality, FixedValuesReplaceTheDesignValuesAndLeaveTheOtherKnobs) {
  const PseudoRealitySpec spec = parse(R"({"knobs": {"wheel_noise": 0.15, "rab_loss": 0.9}})");
  RobotModel design;
  design.rab_range = 0.5;
  for (std::uint64_t k : {1u, 2u, 77u}) {
    const RobotModel m = spec.sample(design, k);
    EXPECT_EQ(m.wheel_noise, 0.15);
    EXPECT_EQ(m.rab_loss, 0.9);
    EXPECT_EQ(m.rab_range, 0.5);
    EXPECT_EQ(m.light_noise, design.light_noise);
  }
  EXPECT_FALSE(spec.varies());
}

TEST(PseudoReality, UniformAndAroundDrawWithinTheirIntervalsAndCoverThem) {
  const PseudoRealitySpec spec = parse(R"({"knobs": {"rab_loss": {"uniform": [0.8, 0.95]}, "light_noise": {"around": 0.5}}})");
  EXPECT_TRUE(spec.varies());
  RobotModel design;
  design.light_noise = 0.1;
  double lo_loss = 1, hi_loss = 0, lo_light = 1, hi_light = 0, sum = 0;
  const int n = 2000;
  for (int k = 1; k <= n; ++k) {
    const RobotModel m = spec.sample(design, static_cast<std::uint64_t>(k));
    lo_loss = std::min(lo_loss, m.rab_loss), hi_loss = std::max(hi_loss, m.rab_loss);
    lo_light = std::min(lo_light, m.light_noise), hi_light = std::max(hi_light, m.light_noise);
    sum += m.light_noise;
  }
  EXPECT_GE(lo_loss, 0.8);
  EXPECT_LE(hi_loss, 0.95);
  EXPECT_LT(lo_loss, 0.81);
  EXPECT_GT(hi_loss, 0.94);
  EXPECT_GE(lo_light, 0.05);
  EXPECT_LE(hi_light, 0.15);
  EXPECT_NEAR(sum / n, 0.1, 0.003);  // uniform around the design value: mean is it
}

TEST(PseudoReality, AroundStaysInTheKnobsDomain) {
  const PseudoRealitySpec spec = parse(R"({"knobs": {"rab_loss": {"around": 0.5}, "rab_range": {"around": 1.0}}})");
  const RobotModel design;  // rab_loss 0.85: 0.85 * 1.5 would exceed 1
  for (std::uint64_t k = 1; k <= 500; ++k) {
    const RobotModel m = spec.sample(design, k);
    EXPECT_LE(m.rab_loss, 1.0);
    EXPECT_GE(m.rab_loss, 0.425);
    EXPECT_GT(m.rab_range, 0.0);
  }
}

TEST(PseudoReality, SampleKIsAPureFunctionOfTheKnobsAndK) {
  const std::string knobs = R"("knobs": {"wheel_noise": {"uniform": [0, 0.2]}, "rab_noise": {"uniform": [0, 0.05]}})";
  const PseudoRealitySpec a = parse("{\"name\": \"a\", " + knobs + "}");
  const PseudoRealitySpec b = parse("{\"name\": \"b\", \"description\": \"other words\", " + knobs + "}");
  const RobotModel design;
  EXPECT_EQ(a.digest, b.digest);  // the description does not move the samples
  std::set<double> seen;
  for (std::uint64_t k = 1; k <= 50; ++k) {
    EXPECT_EQ(a.sample(design, k).wheel_noise, b.sample(design, k).wheel_noise);
    EXPECT_EQ(a.sample(design, k).rab_noise, a.sample(design, k).rab_noise);
    seen.insert(a.sample(design, k).wheel_noise);
  }
  EXPECT_EQ(seen.size(), 50u);
  // A knob's draw does not depend on which other knobs are named.
  const PseudoRealitySpec c = parse(R"({"knobs": {"wheel_noise": {"uniform": [0, 0.2]}, "rab_noise": {"uniform": [0, 0.05]}, "light_noise": 0.9}})");
  EXPECT_NE(c.digest, a.digest);
  const PseudoRealitySpec d = parse(R"({"knobs": {"wheel_noise": {"uniform": [0, 0.2]}, "rab_noise": {"uniform": [0, 0.05]}}})");
  EXPECT_EQ(d.sample(design, 3).wheel_noise, a.sample(design, 3).wheel_noise);
}

TEST(PseudoReality, TheShippedSpecificationsParseAndSayWhereTheyComeFrom) {
  ASSERT_GE(builtin_pseudo_realities().size(), 3u);
  for (const auto& b : builtin_pseudo_realities()) {
    const auto spec = builtin_pseudo_reality(std::string(b.name));
    ASSERT_TRUE(spec) << b.name;
    EXPECT_EQ(spec->name, b.name);
    EXPECT_NE(spec->source.find("Ligot & Birattari"), std::string::npos) << b.name;
  }
  const RobotModel iridia = builtin_pseudo_reality("iridia-transfer")->sample(RobotModel{}, 1);
  EXPECT_EQ(iridia.wheel_noise, 0.15);
  EXPECT_EQ(iridia.rab_loss, 0.9);
  EXPECT_EQ(iridia.light_noise, 0.9);
  const RobotModel tutti = builtin_pseudo_reality("tuttifrutti-transfer")->sample(RobotModel{}, 1);
  EXPECT_EQ(tutti.rab_noise, 0.15);
  EXPECT_EQ(tutti.camera_noise, 0.15);
  const RobotModel around = builtin_pseudo_reality("sampled-around")->sample(RobotModel{}, 1);
  EXPECT_TRUE(around.has_deviations());
}

TEST(PseudoReality, MalformedSpecificationsAreRefusedNamingTheField) {
  const std::vector<std::pair<std::string, std::string>> cases{
      {"", "spec.json: syntax error"},
      {"[]", "document: expected an object"},
      {R"({})", "knobs: missing field"},
      {R"({"knobs": 3})", "knobs: expected an object"},
      {R"({"knobs": {}, "colour": 1})", "colour: unknown field"},
      {R"({"knobs": {"wheel_nois": 0.1}})", "knobs.wheel_nois: unknown knob"},
      {R"({"knobs": {"wheel_noise": -0.1}})", "knobs.wheel_noise: must not be negative"},
      {R"({"knobs": {"rab_loss": 1.5}})", "knobs.rab_loss: must be in [0, 1]"},
      {R"({"knobs": {"rab_loss": {"uniform": [0.5, 1.2]}}})", "knobs.rab_loss.uniform[1]: must be in [0, 1]"},
      {R"({"knobs": {"rab_range": {"uniform": [0, 1]}}})", "knobs.rab_range.uniform[0]: must be positive"},
      {R"({"knobs": {"light_noise": {"uniform": [0.5, 0.1]}}})", "knobs.light_noise.uniform: low must not exceed high"},
      {R"({"knobs": {"light_noise": {"uniform": [0.5]}}})", "knobs.light_noise.uniform: expected [low, high]"},
      {R"({"knobs": {"wheel_deviation": 1.0}})", "knobs.wheel_deviation: must be in [0, 1)"},
      {R"({"knobs": {"light_noise": {"around": 2}}})", "knobs.light_noise.around: must be in [0, 1]"},
      {R"({"knobs": {"light_noise": {"gauss": 2}}})", "knobs.light_noise.gauss: unknown law"},
      {R"({"knobs": {"light_noise": "high"}})", "knobs.light_noise: expected a number"},
      {R"({"knobs": {"light_noise": 1e999}})", "spec.json: number overflow"},
      {R"({"name": 3, "knobs": {}})", "name: expected a string"},
  };
  for (const auto& [text, phrase] : cases) {
    const std::string error = error_of(text);
    EXPECT_NE(error.find(phrase), std::string::npos) << text << " -> " << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  }
}

}  // namespace
}  // namespace sd
