// Arlequin modules 50-55 (Demiurge's Harlequin modules): the perceptron's forward pass
// against values computed by hand (Python, outside this code base), the 25-input encoding
// from a scripted reference model, and the catalogue and dispatch of the six modules.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include "module_test_helpers.hpp"
#include "modules/arlequin.hpp"
#include "modules/conditions.hpp"
#include "robot/reference_model_test_helpers.hpp"

namespace sd {
namespace {

using arlequin::Inputs;
using arlequin::Weights;
using test::module;

constexpr std::size_t kLeft = 0, kRight = 25;  // first weight of each output's row

// ---- forward pass ---------------------------------------------------------------------

TEST(ArlequinNetwork, ForwardPassMatchesHandComputedValues) {
  Weights w{};
  for (std::size_t i = 0; i < 8; ++i) w[kLeft + i] = 0.1;         // proximity -> left
  w[kLeft + 24] = -0.5;                                            // left bias
  for (std::size_t i = 8; i < 16; ++i) w[kRight + i] = -0.2;      // light -> right
  w[kRight + 19] = 1.0;                                            // neighbours -> right
  w[kRight + 24] = 0.4;                                            // right bias
  Inputs x{};
  for (std::size_t i = 0; i < 8; ++i) x[i] = 0.1 * static_cast<double>(i + 1);
  for (std::size_t i = 8; i < 16; ++i) x[i] = 0.5;
  x[19] = 0.5;
  x[24] = 1.0;
  // s0 = 0.1 * 3.6 - 0.5 = -0.14, s1 = -0.2 * 4 + 0.5 + 0.4 = 0.1; o = 1 / (1 + e^(-4.924273 s)).
  const auto o = arlequin::forward(w, x);
  EXPECT_NEAR(o[0], 0.3341669555731117, 1e-14);
  EXPECT_NEAR(o[1], 0.6206780752590112, 1e-14);
  const Actuation a = arlequin::wheels_from_outputs(o);
  EXPECT_NEAR(a.left_cm, -3.979993066245319, 1e-12);
  EXPECT_NEAR(a.right_cm, 2.896273806216268, 1e-12);
  EXPECT_EQ(a.led, kLedUnchanged);
}

TEST(ArlequinNetwork, ZeroSumStopsAWheelAndTheSigmoidSaturatesAtTwelve) {
  Weights w{};
  Inputs x{};
  x[24] = 1.0;
  const Actuation still = arlequin::wheels_from_outputs(arlequin::forward(w, x));
  EXPECT_EQ(still.left_cm, 0.0);
  EXPECT_EQ(still.right_cm, 0.0);
  w[kLeft + 24] = 5.0;
  w[kRight + 24] = -5.0;
  const Actuation spin = arlequin::wheels_from_outputs(arlequin::forward(w, x));
  EXPECT_GT(spin.left_cm, 11.99);
  EXPECT_LE(spin.left_cm, 12.0);
  EXPECT_LT(spin.right_cm, -11.99);
  EXPECT_GE(spin.right_cm, -12.0);
  // Bias 0.2 alone: o = 0.7280704123637115, wheel = -12 + 24 o.
  w[kLeft + 24] = 0.2;
  EXPECT_NEAR(arlequin::wheels_from_outputs(arlequin::forward(w, x)).left_cm, 5.473689896729077, 1e-12);
}

TEST(ArlequinNetwork, EachRowOfWeightsDrivesItsOwnWheel) {
  Inputs x{};
  x[3] = 1.0;
  for (std::size_t k = 0; k < 50; ++k) {
    Weights w{};
    w[k] = 1.0;
    const auto o = arlequin::forward(w, x);
    const bool reads_input_3 = k % 25 == 3;
    EXPECT_EQ(o[0] != 0.5, k < 25 && reads_input_3) << k;
    EXPECT_EQ(o[1] != 0.5, k >= 25 && reads_input_3) << k;
  }
}

// ---- input encoding -------------------------------------------------------------------

class ArlequinInputs : public testing::Test {
 protected:
  Inputs step(const std::vector<test::Packet>& packets = {}) {
    test::set_packets(swarm, 0, packets);
    rm.update(swarm, 0);
    return arlequin::encode_inputs(rm);
  }
  void set_ground(double left, double centre, double right) { swarm.ground[0] = {left, centre, right}; }
  SwarmState swarm = test::silent_swarm(4);
  ReferenceModel rm;
};

TEST_F(ArlequinInputs, RawProximityAndLightPassThroughInSensorOrder) {
  for (std::size_t k = 0; k < 8; ++k) {
    swarm.proximity[0][k] = 0.05 + 0.1 * static_cast<double>(k);
    swarm.light[0][k] = 0.9 - 0.1 * static_cast<double>(k);
  }
  const Inputs x = step();
  for (std::size_t k = 0; k < 8; ++k) {
    EXPECT_EQ(x[k], swarm.proximity[0][k]) << k;
    EXPECT_EQ(x[8 + k], swarm.light[0][k]) << k;
  }
  EXPECT_EQ(x[24], 1.0);
}

TEST_F(ArlequinInputs, GroundIsZeroOnBlackOneOnWhiteAndTheRawReadingOnGrey) {
  // Grey floor: the three raw readings, each its own (our substitute for DEMI's samples).
  set_ground(0.45, 0.5, 0.55);
  Inputs x = step();
  EXPECT_EQ(x[16], 0.45);
  EXPECT_EQ(x[17], 0.5);
  EXPECT_EQ(x[18], 0.55);
  // Black: the 5-step majority needs more than 10 of 15 samples, i.e. 4 steps here (the
  // window still holds one grey step); until then the raw readings pass.
  set_ground(0.01, 0.02, 0.0);
  for (int k = 0; k < 3; ++k) {
    x = step();
    EXPECT_EQ(x[16], 0.01) << k;
  }
  x = step();
  EXPECT_EQ(x[16], 0.0);
  EXPECT_EQ(x[17], 0.0);
  EXPECT_EQ(x[18], 0.0);
  // White: once the majority says so, all three read 1, whatever the raw values.
  set_ground(0.9, 0.88, 0.86);
  for (int k = 0; k < 5; ++k) x = step();
  EXPECT_EQ(x[16], 1.0);
  EXPECT_EQ(x[17], 1.0);
  EXPECT_EQ(x[18], 1.0);
}

TEST_F(ArlequinInputs, NeighbourCountInputSaturatesTowardsOne) {
  EXPECT_EQ(step()[19], 0.0);
  EXPECT_NEAR(step({{30.0, 0.3, 1}})[19], 0.4621171572600098, 1e-15);
  EXPECT_NEAR(step({{30.0, 0.3, 1}, {40.0, 1.0, 2}, {50.0, -2.0, 3}})[19], 0.9051482536448664, 1e-15);
}

TEST_F(ArlequinInputs, NeighbourDirectionIsTheMeanBufferedPositionOnFourDiagonals) {
  Inputs x = step();
  for (std::size_t k = 20; k < 24; ++k) EXPECT_EQ(x[k], 0.0) << "empty buffer";
  // 10 cm straight ahead, then 20 cm to the left: mean position (5, 10) cm.
  step({{10.0, 0.0, 1}});
  x = step({{20.0, kPi / 2.0, 2}});
  EXPECT_NEAR(x[20], 10.606601717798213, 1e-12);  // 45 deg
  EXPECT_NEAR(x[21], 3.535533905932738, 1e-12);   // 135 deg
  EXPECT_EQ(x[22], 0.0);                          // 225 deg: negative, clipped
  EXPECT_EQ(x[23], 0.0);                          // 315 deg
  // Ten quiet steps later the first message (11 steps old) has left the buffer; the second
  // is alone: (0, 20) cm.
  for (int k = 0; k < 10; ++k) x = step();
  EXPECT_NEAR(x[20], 20.0 * std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(x[21], 20.0 * std::sqrt(0.5), 1e-12);
  EXPECT_EQ(x[22], 0.0);
  EXPECT_EQ(x[23], 0.0);
  x = step();
  for (std::size_t k = 20; k < 24; ++k) EXPECT_EQ(x[k], 0.0) << "buffer emptied";
}

// ---- catalogue, dispatch and shipped weights -------------------------------------------

TEST(ArlequinModules, SixParameterlessBehavioursThatReadEveryNetworkInput) {
  const char* names[] = {"Exploration", "Stop", "Phototaxis", "Anti-phototaxis", "Attraction", "Repulsion"};
  for (int d = 0; d < 6; ++d) {
    const ModuleSpec* spec = find_module(ModuleKind::Behaviour, 50 + d);
    ASSERT_NE(spec, nullptr) << 50 + d;
    EXPECT_EQ(spec->name, names[d]);
    EXPECT_EQ(spec->flavour(), Flavour::Arlequin);
    EXPECT_TRUE(spec->parameters.empty());
    EXPECT_EQ(spec->inputs, kProximityInput | kLightInput | kGroundInput | kRangeAndBearingInput);
  }
  EXPECT_EQ(find_module(ModuleKind::Behaviour, 56), nullptr);
}

TEST(ArlequinModules, ConditionsAreTheChocolateSix) {
  ReferenceModel rm;
  rm.ground = 0.0;
  rm.ground_demiurge = 0.0;  // Arlequin's floor conditions read Demiurge's filter (demiurge_floor_conditions_test)
  rm.neighbours = 4;
  for (int d = 0; d < 6; ++d) {
    const ModuleSpec* chocolate = find_module(ModuleKind::Condition, 10 + d);
    const ModuleSpec* arlequin = find_module(ModuleKind::Condition, 50 + d);
    ASSERT_NE(arlequin, nullptr) << 50 + d;
    EXPECT_EQ(arlequin->name, chocolate->name);
    EXPECT_EQ(arlequin->inputs, chocolate->inputs);
    ASSERT_EQ(arlequin->parameters.size(), chocolate->parameters.size());
    for (std::size_t p = 0; p < arlequin->parameters.size(); ++p)
      EXPECT_EQ(arlequin->parameters[p].token, chocolate->parameters[p].token);
    Rng a(3), b(3);
    const ModuleInstance c = module(10 + d, {d == 3 || d == 4 ? 3.0 : 0.6, 2.0});
    ModuleInstance other = c;
    other.id = 50 + d;
    for (int k = 0; k < 50; ++k) EXPECT_EQ(check_condition(c, rm, a), check_condition(other, rm, b)) << d;
  }
}

TEST(ArlequinModules, ShippedWeightsAreSixDistinctNetworksWithinTheBounds) {
  for (int id = 50; id <= 55; ++id) {
    const Weights& w = arlequin::shipped_weights(id);
    for (const double v : w) {
      EXPECT_TRUE(std::isfinite(v)) << id;
      EXPECT_LE(std::abs(v), arlequin::kWeightBound) << id;
    }
    for (int other = 50; other < id; ++other) EXPECT_NE(w, arlequin::shipped_weights(other)) << id << " vs " << other;
  }
  EXPECT_THROW(arlequin::shipped_weights(49), std::out_of_range);
  EXPECT_THROW(arlequin::shipped_weights(56), std::out_of_range);
}

TEST(ArlequinModules, RunBehaviourDrivesTheModulesShippedNetwork) {
  SwarmState swarm = test::silent_swarm(3);
  swarm.proximity[0] = {0.4, 0.1, 0, 0, 0, 0, 0, 0.2};
  swarm.light[0] = {0, 0, 0.3, 0.6, 0.2, 0, 0, 0};
  swarm.ground[0] = {0.5, 0.48, 0.52};
  test::set_packets(swarm, 0, {{15.0, 0.7, 1}, {40.0, -2.5, 2}});
  ReferenceModel rm;
  rm.update(swarm, 0);
  for (int id = 50; id <= 55; ++id) {
    BehaviourMemory memory;
    Rng rng(1), untouched(1);
    const Actuation a = run_behaviour(module(id), memory, rm, rng);
    const Actuation expected = arlequin::drive(arlequin::shipped_weights(id), rm);
    EXPECT_EQ(a.left_cm, expected.left_cm) << id;
    EXPECT_EQ(a.right_cm, expected.right_cm) << id;
    EXPECT_EQ(a.led, kLedUnchanged) << id;
    EXPECT_TRUE(test::same_rng_state(rng, untouched)) << id << ": a network draws no random numbers";
  }
}

TEST(ArlequinWeights, DocumentsAreReadExactlyAndMalformedOnesNamed) {
  // Built with a stream: GCC 12 reports a false -Wrestrict on chains of std::string +.
  std::ostringstream l, r;
  for (int i = 0; i < 25; ++i) {
    l << (i ? ", " : "[") << i << ".125";
    r << (i ? ", " : "[") << (i == 24 ? "-4.999999999999999" : "0.1");
  }
  const std::string left = l.str(), right = r.str();
  std::ostringstream d;
  d << R"({"weights": {"left": )" << left << R"(], "right": )" << right << "]}}";
  const std::string doc = d.str();
  const Weights w = arlequin::weights_from_json(doc, "doc");
  EXPECT_EQ(w[3], 3.125);
  EXPECT_EQ(w[25], 0.1);
  EXPECT_EQ(w[49], -4.999999999999999);
  const auto message = [](const std::string& text) {
    try {
      arlequin::weights_from_json(text, "f.json");
    } catch (const std::runtime_error& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message("{").find("f.json: not JSON"), std::string::npos);
  // Found by fuzz_weights: a number no double holds escaped as nlohmann's out_of_range.
  EXPECT_NE(message(R"({"weights": {"left": [2.9061e3087]}})").find("f.json: not JSON (number overflow"), std::string::npos);
  EXPECT_NE(message("{\"weights\": {\"left\": []}}").find("weights.left must be an array of 25"), std::string::npos);
  std::ostringstream no_right, bad_right;
  no_right << R"({"weights": {"left": )" << left << "]}}";
  bad_right << R"({"weights": {"left": )" << left << R"(], "right": ["x")" << right.substr(4) << "]}}";
  EXPECT_NE(message(no_right.str()).find("weights.right"), std::string::npos);
  EXPECT_NE(message(bad_right.str()).find("weights.right[0] is not a finite number"), std::string::npos);
}

}  // namespace
}  // namespace sd
