// RM1.2 proximity and light vectors (demiurge-epuck-dao's ReferenceModel1Dot2): P = sum of p_i
// at the reported sensor angles, length clipped to 1; light = unit vector towards sum of l_i at
// the same angles if any l_i > 0.2, else zero.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "reference_model_test_helpers.hpp"

namespace sd {
namespace {

using test::kAngleTolerance;
using test::kReportedAngles;
using test::unit_at;

class RobotVectors : public testing::Test {
 protected:
  void update() { rm.update(swarm, 0); }
  SwarmState swarm = test::silent_swarm();
  ReferenceModel rm;
};

TEST_F(RobotVectors, SensorDirectionsAreTheReportedAngles) {
  const auto& directions = sensor_directions();
  for (std::size_t k = 0; k < 8; ++k) {
    EXPECT_NEAR(directions[k].length(), 1.0, 1e-12);
    EXPECT_NEAR(wrap_unsigned(directions[k].angle()), kReportedAngles[k], kAngleTolerance) << "sensor " << k;
  }
}

TEST_F(RobotVectors, SingleProximityReadingPointsAtItsSensor) {
  for (std::size_t k = 0; k < 8; ++k) {
    swarm.proximity[0] = {};
    swarm.proximity[0][k] = 0.7;
    update();
    EXPECT_NEAR(rm.proximity.length(), 0.7, 1e-12) << "sensor " << k;
    EXPECT_NEAR(rm.proximity_value(), 0.7, 1e-12);
    EXPECT_NEAR(wrap_unsigned(rm.proximity.angle()), kReportedAngles[k], kAngleTolerance) << "sensor " << k;
    EXPECT_NEAR(rm.proximity_angle(), wrap_signed(kReportedAngles[k]), kAngleTolerance);
  }
}

TEST_F(RobotVectors, ProximityReadingsAddUpAsVectors) {
  swarm.proximity[0] = {0.3, 0.0, 0.0, 0.0, 0.0, 0.0, 0.1, 0.2};
  update();
  const Vec2 expected =
      unit_at(kReportedAngles[0]) * 0.3 + unit_at(kReportedAngles[6]) * 0.1 + unit_at(kReportedAngles[7]) * 0.2;
  EXPECT_NEAR(rm.proximity.x, expected.x, 1e-3);
  EXPECT_NEAR(rm.proximity.y, expected.y, 1e-3);
  EXPECT_LT(rm.proximity.length(), 1.0);
  EXPECT_TRUE(std::ranges::equal(rm.raw_proximity, swarm.proximity[0]));
}

TEST_F(RobotVectors, ProximityIsClippedToLengthOne) {
  swarm.proximity[0] = {1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0};  // |sum| = 2 cos(16.5 deg) ~ 1.92
  update();
  const Vec2 sum = unit_at(kReportedAngles[0]) + unit_at(kReportedAngles[1]);
  EXPECT_NEAR(rm.proximity.length(), 1.0, 1e-12);
  EXPECT_NEAR(rm.proximity.angle(), sum.angle(), kAngleTolerance);
  swarm.proximity[0].fill(1.0);  // all sensors saturated: still length 1 (sum is not zero)
  update();
  EXPECT_NEAR(rm.proximity.length(), 1.0, 1e-12);
}

TEST_F(RobotVectors, NoProximityReadingGivesTheZeroVector) {
  update();
  EXPECT_EQ(rm.proximity, (Vec2{0.0, 0.0}));
}

TEST_F(RobotVectors, LightIsAUnitVectorTowardsTheWeightedSum) {
  swarm.light[0] = {0.5, 0.0, 0.1, 0.0, 0.0, 0.0, 0.0, 0.0};
  update();
  const Vec2 sum = unit_at(kReportedAngles[0]) * 0.5 + unit_at(kReportedAngles[2]) * 0.1;
  EXPECT_NEAR(rm.light.length(), 1.0, 1e-12);
  EXPECT_NEAR(rm.light.angle(), sum.angle(), kAngleTolerance);
  EXPECT_EQ(rm.light_value(), 1.0);
  EXPECT_TRUE(std::ranges::equal(rm.raw_light, swarm.light[0]));
}

TEST_F(RobotVectors, OneReadingAboveTwoTenthsIsEnough) {
  for (std::size_t k = 0; k < 8; ++k) {
    swarm.light[0] = {};
    swarm.light[0][k] = 0.21;
    update();
    EXPECT_NEAR(rm.light.length(), 1.0, 1e-12) << "sensor " << k;
    EXPECT_NEAR(wrap_unsigned(rm.light.angle()), kReportedAngles[k], kAngleTolerance) << "sensor " << k;
  }
}

TEST_F(RobotVectors, NoReadingAboveTwoTenthsGivesZeroLight) {
  swarm.light[0].fill(0.2);  // 0.2 is not above 0.2, however many sensors read it
  update();
  EXPECT_EQ(rm.light, (Vec2{0.0, 0.0}));
  EXPECT_EQ(rm.light_value(), 0.0);
  swarm.light[0] = {0.15, 0.19, 0.0, 0.0, 0.0, 0.0, 0.0, 0.2};
  update();
  EXPECT_EQ(rm.light, (Vec2{0.0, 0.0}));
  // And it comes back as soon as one sensor exceeds the threshold.
  swarm.light[0][3] = 0.2000001;
  update();
  EXPECT_NEAR(rm.light.length(), 1.0, 1e-12);
}

TEST_F(RobotVectors, LightAndProximityHaveNoMemory) {
  swarm.light[0][0] = 0.9;
  swarm.proximity[0][0] = 0.9;
  update();
  swarm.light[0] = {};
  swarm.proximity[0] = {};
  update();
  EXPECT_EQ(rm.light, (Vec2{0.0, 0.0}));
  EXPECT_EQ(rm.proximity, (Vec2{0.0, 0.0}));
}

}  // namespace
}  // namespace sd
