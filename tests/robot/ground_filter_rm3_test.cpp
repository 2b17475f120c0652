// RM3.0 ground reading (demiurge-epuck-dao ReferenceModel3Dot0::GetGroundReading), which the
// TuttiFrutti floor conditions read: the same 5-step x 3-sensor majority as RM1.x, but a
// sample is black below 0.1 and otherwise white above 0.8 (RM1.x: 0.03 and 0.85).
#include <gtest/gtest.h>

#include <array>

#include "reference_model_test_helpers.hpp"

namespace sd {
namespace {

using Rm3GroundFilter = test::GroundFilterTest;

TEST_F(Rm3GroundFilter, NoisyBlackIsBlackForRm3Only) {
  // A black floor with the sensor noise reads up to 0.05: RM1.x calls 0.04 gray, RM3.0 black.
  for (int k = 0; k < 5; ++k) step({0.04, 0.0, 0.04});
  EXPECT_EQ(rm.ground_rm3, 0.0);
  EXPECT_EQ(rm.ground, 0.5);  // only 5 of 15 samples below 0.03
  for (int k = 0; k < 5; ++k) step({0.09, 0.09, 0.09});
  EXPECT_EQ(rm.ground_rm3, 0.0);
  step({0.1, 0.1, 0.1});
  step({0.1, 0.1, 0.1});
  EXPECT_EQ(rm.ground_rm3, 0.5) << "0.1 is not below 0.1: 9 of 15";
}

TEST_F(Rm3GroundFilter, WhiteAbovePointEight) {
  for (int k = 0; k < 5; ++k) step({0.82, 0.82, 0.82});
  EXPECT_EQ(rm.ground_rm3, 1.0);
  EXPECT_EQ(rm.ground, 0.5);
  rm.reset();
  for (int k = 0; k < 5; ++k) step({0.8, 0.8, 0.8});
  EXPECT_EQ(rm.ground_rm3, 0.5);
}

TEST_F(Rm3GroundFilter, GrayStaysGrayAndResetForgets) {
  for (int k = 0; k < 5; ++k) step({0.5, 0.45, 0.55});
  EXPECT_EQ(rm.ground_rm3, 0.5);
  for (int k = 0; k < 5; ++k) step({0.0, 0.0, 0.0});
  EXPECT_EQ(rm.ground_rm3, 0.0);
  rm.reset();
  EXPECT_EQ(rm.ground_rm3, 0.5);
  step({0.0, 0.0, 0.0});
  EXPECT_EQ(rm.ground_rm3, 0.5) << "3 samples are not a majority";
}

}  // namespace
}  // namespace sd
