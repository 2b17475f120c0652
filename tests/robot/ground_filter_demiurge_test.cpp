// Demiurge's RM3.0 ground reading (AmmarHsn/demiurge-epuck-dao ReferenceModel3Dot0), which the
// Coconut floor conditions read: the last 10 steps x 3 sensors; black if more than 8 of the 30
// samples are below 0.02, else white if more than 8 are above 0.97, else gray.
#include <gtest/gtest.h>

#include <array>

#include "reference_model_test_helpers.hpp"

namespace sd {
namespace {

using DemiurgeGroundFilter = test::GroundFilterTest;

TEST_F(DemiurgeGroundFilter, NineSamplesBelowPointZeroTwoAreBlack) {
  step({0.01, 0.01, 0.01});
  step({0.01, 0.01, 0.01});
  EXPECT_EQ(rm.ground_demiurge, 0.5) << "6 samples are not more than 8";
  step({0.01, 0.01, 0.5});
  EXPECT_EQ(rm.ground_demiurge, 0.5) << "8 samples are not more than 8";
  step({0.01, 0.5, 0.5});
  EXPECT_EQ(rm.ground_demiurge, 0.0);
  EXPECT_EQ(rm.ground, 0.5) << "RM1.2 needs more than 10 of its 15";
  // 0.02 is not below 0.02; the nine black samples stay in the window for 10 steps.
  for (int k = 0; k < 6; ++k) step({0.02, 0.02, 0.02});
  EXPECT_EQ(rm.ground_demiurge, 0.0);
  step({0.02, 0.02, 0.02});
  EXPECT_EQ(rm.ground_demiurge, 0.5) << "the first step has left the window: 6 of 30";
}

TEST_F(DemiurgeGroundFilter, WhiteAbovePointNineSevenAndBlackFirst) {
  for (int k = 0; k < 3; ++k) step({0.98, 0.98, 0.98});
  EXPECT_EQ(rm.ground_demiurge, 1.0);
  rm.reset();
  for (int k = 0; k < 10; ++k) step({0.97, 0.97, 0.97});
  EXPECT_EQ(rm.ground_demiurge, 0.5) << "0.97 is not above 0.97";
  rm.reset();
  for (int k = 0; k < 8; ++k) step({0.0, 1.0, 1.0});
  EXPECT_EQ(rm.ground_demiurge, 1.0) << "8 black, 16 white";
  step({0.0, 1.0, 1.0});
  EXPECT_EQ(rm.ground_demiurge, 0.0) << "9 black and 18 white: black is tested first";
}

TEST_F(DemiurgeGroundFilter, ResetForgets) {
  for (int k = 0; k < 10; ++k) step({0.0, 0.0, 0.0});
  EXPECT_EQ(rm.ground_demiurge, 0.0);
  rm.reset();
  EXPECT_EQ(rm.ground_demiurge, 0.5);
  step({0.0, 0.0, 0.0});
  EXPECT_EQ(rm.ground_demiurge, 0.5);
}

}  // namespace
}  // namespace sd
