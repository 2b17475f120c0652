// W(v) of RM1.2 (ARGoS3-AutoMoDe's AutoMoDeBehaviour): outer wheel 12 cm/s,
// inner 12 cos(theta), theta exactly 0 or pi turns right (left wheel 12), the zero vector
// stops (where AutoMoDe's W(v) gives NaN wheel speeds).
#include <gtest/gtest.h>

#include <cmath>

#include "module_test_helpers.hpp"

namespace sd {
namespace {

using test::expect_wheels;
using test::kFull;

TEST(ModulesWheelsTowards, StraightAheadDrivesBothWheelsAtFullSpeed) {
  expect_wheels(wheels_towards({1.0, 0.0}), {kFull, kFull, 0});
  expect_wheels(wheels_towards({0.01, 0.0}), {kFull, kFull, 0});  // length does not matter
}

TEST(ModulesWheelsTowards, StraightBehindSpinsRightInPlace) {
  // theta = pi is not in the open interval (0, pi): left wheel 12, right 12 cos(pi) = -12.
  expect_wheels(wheels_towards({-1.0, 0.0}), {kFull, -kFull, 0});
  expect_wheels(wheels_towards({-1.0, -0.0}), {kFull, -kFull, 0});
}

TEST(ModulesWheelsTowards, LeftAndRightAxes) {
  expect_wheels(wheels_towards({0.0, 1.0}), {0.0, kFull, 0}, 1e-12);   // theta = pi/2
  expect_wheels(wheels_towards({0.0, -1.0}), {kFull, 0.0, 0}, 1e-12);  // theta = 3pi/2
}

TEST(ModulesWheelsTowards, EveryQuadrantMatchesTheSpecFormula) {
  for (int deg = -179; deg <= 180; deg += 7) {
    const double a = degrees_to_radians(deg);
    for (const double length : {0.2, 1.0, 37.0}) {
      const Vec2 v = Vec2::polar(length, a);
      SCOPED_TRACE(testing::Message() << "angle " << deg << " deg, length " << length);
      expect_wheels(wheels_towards(v), test::spec_wheels(v));
    }
  }
}

TEST(ModulesWheelsTowards, OuterWheelIsAlwaysTwelveAndInnerTwelveCos) {
  const Vec2 front_left{1.0, 1.0}, back_left{-1.0, 2.0}, back_right{-3.0, -1.0}, front_right{2.0, -0.5};
  const Actuation fl = wheels_towards(front_left);
  EXPECT_EQ(fl.right_cm, kFull);
  EXPECT_NEAR(fl.left_cm, kFull * std::cos(kPi / 4.0), 1e-12);
  const Actuation bl = wheels_towards(back_left);
  EXPECT_EQ(bl.right_cm, kFull);
  EXPECT_NEAR(bl.left_cm, kFull * -1.0 / std::sqrt(5.0), 1e-12);
  const Actuation br = wheels_towards(back_right);
  EXPECT_EQ(br.left_cm, kFull);
  EXPECT_NEAR(br.right_cm, kFull * -3.0 / std::sqrt(10.0), 1e-12);
  const Actuation fr = wheels_towards(front_right);
  EXPECT_EQ(fr.left_cm, kFull);
  EXPECT_NEAR(fr.right_cm, kFull * 2.0 / std::sqrt(4.25), 1e-12);
}

TEST(ModulesWheelsTowards, ZeroVectorStopsInsteadOfNan) {
  const Actuation a = wheels_towards({0.0, 0.0});
  EXPECT_EQ(a.left_cm, 0.0);
  EXPECT_EQ(a.right_cm, 0.0);
  EXPECT_FALSE(std::isnan(a.left_cm) || std::isnan(a.right_cm));
}

}  // namespace
}  // namespace sd
