// RM1.2 ground reading (demiurge-epuck-dao's ReferenceModel1Dot2): over the last 5 steps x 3
// sensors, more than 10 samples < 0.03 -> black (0); else more than 10 samples > 0.85 -> white
// (1); else gray (0.5).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>

#include "reference_model_test_helpers.hpp"

namespace sd {
namespace {

using Floor = std::array<double, 3>;
constexpr Floor kBlack{0.0, 0.0, 0.0};
constexpr Floor kGray{0.5, 0.5, 0.5};
constexpr Floor kWhite{1.0, 1.0, 1.0};

class RobotGroundFilter : public testing::Test {
 protected:
  /// One control step of robot 0 on `floor`; returns the filtered ground value.
  double step(const Floor& floor) {
    swarm.ground[0] = floor;
    rm.update(swarm, 0);
    return rm.ground;
  }
  SwarmState swarm = test::silent_swarm();
  ReferenceModel rm;
};

TEST_F(RobotGroundFilter, StartsGrayWhateverTheFloor) {
  EXPECT_EQ(rm.ground, 0.5);
  for (const Floor& f : {kBlack, kWhite}) {
    rm.reset();
    for (int k = 1; k <= 3; ++k) EXPECT_EQ(step(f), 0.5) << "step " << k;  // at most 9 samples
  }
}

TEST_F(RobotGroundFilter, BlackAfterFourBlackSteps) {
  for (int k = 0; k < 3; ++k) step(kBlack);
  EXPECT_EQ(step(kBlack), 0.0);  // 12 of 12 samples black
  for (int k = 0; k < 10; ++k) EXPECT_EQ(step(kBlack), 0.0);
}

TEST_F(RobotGroundFilter, WhiteAfterFourWhiteSteps) {
  for (int k = 0; k < 3; ++k) EXPECT_EQ(step(kWhite), 0.5);
  EXPECT_EQ(step(kWhite), 1.0);
}

TEST_F(RobotGroundFilter, ElevenOfFifteenSamplesDecide) {
  // 3 + 3 + 3 + 2 + 0 = 11 black samples -> black.
  for (const Floor& f : {kBlack, kBlack, kBlack, Floor{0.0, 0.0, 0.5}, kGray}) step(f);
  EXPECT_EQ(rm.ground, 0.0);
  rm.reset();
  // 3 + 3 + 3 + 1 + 0 = 10 -> gray.
  for (const Floor& f : {kBlack, kBlack, kBlack, Floor{0.0, 0.5, 0.5}, kGray}) step(f);
  EXPECT_EQ(rm.ground, 0.5);
  rm.reset();
  for (const Floor& f : {kWhite, kWhite, kWhite, Floor{1.0, 0.5, 1.0}, kGray}) step(f);
  EXPECT_EQ(rm.ground, 1.0);
  rm.reset();
  for (const Floor& f : {kWhite, kWhite, kWhite, Floor{1.0, 0.5, 0.5}, kGray}) step(f);
  EXPECT_EQ(rm.ground, 0.5);
}

TEST_F(RobotGroundFilter, ThresholdsAreStrict) {
  for (int k = 0; k < 5; ++k) step({0.0299, 0.0299, 0.0299});
  EXPECT_EQ(rm.ground, 0.0);
  rm.reset();
  for (int k = 0; k < 5; ++k) step({0.03, 0.03, 0.03});
  EXPECT_EQ(rm.ground, 0.5);
  rm.reset();
  for (int k = 0; k < 5; ++k) step({0.8501, 0.8501, 0.8501});
  EXPECT_EQ(rm.ground, 1.0);
  rm.reset();
  for (int k = 0; k < 5; ++k) step({0.85, 0.85, 0.85});
  EXPECT_EQ(rm.ground, 0.5);
}

TEST_F(RobotGroundFilter, SingleNoisySampleDoesNotFlipTheReading) {
  for (int k = 0; k < 8; ++k) step(kBlack);
  EXPECT_EQ(step({0.0, 0.6, 0.0}), 0.0);
  EXPECT_EQ(step({1.0, 0.0, 0.0}), 0.0);
  rm.reset();
  for (int k = 0; k < 8; ++k) step(kWhite);
  EXPECT_EQ(step({1.0, 0.0, 1.0}), 1.0);
  EXPECT_EQ(step({0.4, 1.0, 1.0}), 1.0);
}

TEST_F(RobotGroundFilter, OnlyTheLastFiveStepsCount) {
  for (int k = 0; k < 20; ++k) step(kWhite);
  // White -> black: 12 white after one black step, gray after two and three, black after four.
  EXPECT_EQ(step(kBlack), 1.0);
  EXPECT_EQ(step(kBlack), 0.5);
  EXPECT_EQ(step(kBlack), 0.5);
  EXPECT_EQ(step(kBlack), 0.0);
  // Two gray steps leave 9 black samples: gray.
  EXPECT_EQ(step(kGray), 0.0);
  EXPECT_EQ(step(kGray), 0.5);
}

TEST_F(RobotGroundFilter, KeepsTheRawReadings) {
  step({0.1, 0.2, 0.3});
  EXPECT_TRUE(std::ranges::equal(rm.raw_ground, Floor{0.1, 0.2, 0.3}));
}

TEST_F(RobotGroundFilter, ResetForgetsTheHistory) {
  for (int k = 0; k < 5; ++k) step(kBlack);
  rm.reset();
  EXPECT_EQ(rm.ground, 0.5);
  EXPECT_EQ(step(kBlack), 0.5);
}

TEST_F(RobotGroundFilter, EachRobotReadsItsOwnSensors) {
  swarm.ground[1] = kWhite;
  for (int k = 0; k < 5; ++k) step(kBlack);
  EXPECT_EQ(rm.ground, 0.0);
  ReferenceModel other;
  for (int k = 0; k < 5; ++k) other.update(swarm, 1);
  EXPECT_EQ(other.ground, 1.0);
}

}  // namespace
}  // namespace sd
