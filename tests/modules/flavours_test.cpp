// TuttiFrutti, Coconut and Maple control laws (ARGoS3-AutoMoDe's tuttifrutti and
// BehaviorTree branches, Demiurge).
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "modules/behaviours.hpp"
#include "modules/conditions.hpp"
#include "module_test_helpers.hpp"

namespace sd {
namespace {

using test::expect_wheels;
using test::module;
using test::spec_wheels;

constexpr std::uint32_t kGreen = 0x00ff00, kYellow = 0xffff00, kCyan = 0x00ffff;

/// A reference model that sees the given blobs.
struct Scene {
  ReferenceModel rm;
  std::array<CameraBlob, 4> blobs{};
  Scene(std::initializer_list<CameraBlob> seen) {
    std::size_t k = 0;
    for (const CameraBlob& b : seen) blobs[k++] = b;
    rm.blobs = std::span<const CameraBlob>(blobs.data(), k);
  }
};

CameraBlob blob(std::uint32_t rgb, double angle_deg, double distance_cm) {
  return {rgb, Vec2::polar(1.0, angle_deg * kPi / 180.0), distance_cm};
}

TEST(TuttiFrutti, BehavioursShowTheirLedColour) {
  ReferenceModel rm;
  Rng rng(1);
  BehaviourMemory m;
  EXPECT_EQ(run_behaviour(module(21, {4}), m, rm, rng).led, kYellow);
  EXPECT_EQ(run_behaviour(module(20, {10, 6}), m, rm, rng).led, kCyan);
  EXPECT_EQ(run_behaviour(module(24, {3, 0}), m, rm, rng).led, 0u);  // cle 0: LEDs off
  // Chocolate behaviours leave the LEDs alone.
  EXPECT_EQ(run_behaviour(module(11), m, rm, rng).led, kLedUnchanged);
  EXPECT_EQ(run_behaviour(module(41), m, rm, rng).led, kLedUnchanged);
}

TEST(TuttiFrutti, GoToColorSteersTowardsTheWeightedBlobsOfItsColour) {
  // Two green blobs at +60 deg (20 cm) and -30 deg (50 cm); a yellow one that must be
  // ignored, and a green one closer than 6 cm that must be ignored too.
  Scene s({blob(kGreen, 60, 20), blob(kGreen, -30, 50), blob(kYellow, 180, 10), blob(kGreen, 180, 5)});
  const Vec2 c = Vec2::polar(1.0 / 21.0, 60 * kPi / 180) + Vec2::polar(1.0 / 51.0, -30 * kPi / 180);
  EXPECT_NEAR(color_vector(s.rm, kGreen).x, c.x, 1e-15);
  Rng rng(1);
  BehaviourMemory m;
  const Actuation a = run_behaviour(module(28, {1, 5, 1}), m, s.rm, rng);  // vel 1, cle 5, clr 1 green
  expect_wheels(a, spec_wheels(c * (1.0 / c.length())));
  EXPECT_EQ(a.led, 0xff00ffu);
  // GoAwayColor turns the other way.
  expect_wheels(run_behaviour(module(29, {1, 5, 1}), m, s.rm, rng), spec_wheels(c * (-1.0 / c.length())));
}

TEST(TuttiFrutti, WithoutItsColourGoToColorDrivesStraightAndAvoidsObstacles) {
  Scene s({blob(kYellow, 90, 20)});
  s.rm.proximity = Vec2::polar(0.5, 0.3);  // obstacle ahead-left
  Rng rng(1);
  BehaviourMemory m;
  expect_wheels(run_behaviour(module(28, {1, 0, 1}), m, s.rm, rng), spec_wheels(Vec2{1, 0} - s.rm.proximity * 6.0));
  expect_wheels(run_behaviour(module(29, {1, 0, 1}), m, s.rm, rng), spec_wheels(Vec2{1, 0} - s.rm.proximity * 5.0));
}

TEST(TuttiFrutti, ColorDetectionFiresOnlyOnItsColourAtSixCentimetresOrMore) {
  Rng rng(3);
  Scene near_only({blob(kGreen, 0, 5.9)});
  Scene far({blob(kGreen, 0, 6.0)});
  const ModuleInstance detect_green = module(27, {1.0, 1});
  const ModuleInstance detect_cyan = module(27, {1.0, 6});
  EXPECT_FALSE(check_condition(detect_green, near_only.rm, rng));
  EXPECT_TRUE(check_condition(detect_green, far.rm, rng));
  EXPECT_FALSE(check_condition(detect_cyan, far.rm, rng));
  int fired = 0;
  for (int k = 0; k < 4000; ++k) fired += check_condition(module(27, {0.25, 1}), far.rm, rng);
  EXPECT_NEAR(fired / 4000.0, 0.25, 5 * std::sqrt(0.25 * 0.75 / 4000));
}

TEST(Coconut, BallisticWithAvoidanceDrivesAwayFromObstacles) {
  ReferenceModel rm;
  Rng rng(1);
  BehaviourMemory m;
  expect_wheels(run_behaviour(module(30, {0}), m, rm, rng), spec_wheels({1, 0}));  // nothing: straight
  rm.proximity = Vec2::polar(0.4, 0.5);
  expect_wheels(run_behaviour(module(30, {0}), m, rm, rng), spec_wheels(rm.proximity * -1.0));
}

TEST(Coconut, RandomTurnSpinsAwayFromTheObstacleForTheDrawnSteps) {
  ReferenceModel rm;
  rm.proximity = Vec2::polar(0.5, -0.4);  // obstacle ahead on the right
  Rng rng(7), replay(7);
  BehaviourMemory m;
  const ModuleInstance b = module(30, {1, 20});
  // First step: a draw in [0, 20); spin left (angle pi - 1e-4 has a positive y).
  const Actuation first = run_behaviour(b, m, rm, rng);
  const auto drawn = static_cast<int>(replay.uniform_int(0, 20));
  expect_wheels(first, spec_wheels(Vec2::polar(1.0, kPi - 1e-4)));
  EXPECT_LT(first.left_cm, 0.0);
  rm.proximity = {};
  // It keeps spinning for the drawn number of further steps, then goes straight.
  for (int k = 0; k < drawn; ++k) EXPECT_LT(run_behaviour(b, m, rm, rng).left_cm, 0.0) << k;
  expect_wheels(run_behaviour(b, m, rm, rng), spec_wheels({1, 0}));
}

TEST(Coconut, RandomWalkUsesOneDrawForLengthAndAngle) {
  ReferenceModel rm;
  Rng rng(11), replay(11);
  BehaviourMemory m;
  const double mu = 1.8, rho = 0.4;
  const ModuleInstance b = module(30, {2, 0, mu, rho});  // exp, (rwm inactive), mu, rho
  const Actuation a = run_behaviour(b, m, rm, rng);
  const double u = replay.uniform();
  const double angle = 2.0 * std::atan((1.0 - rho) / (1.0 + rho) * std::tan(kPi * (u - 0.5)));
  const int steps = static_cast<int>(std::ceil(std::pow(u, 1.0 / (1.0 - mu)) + 0.5));
  expect_wheels(a, spec_wheels(Vec2::polar(1.0, angle)));
  EXPECT_EQ(m.walk_steps, steps);
  EXPECT_GE(steps, 2);
  // The same heading is kept for the rest of the walk.
  for (int k = 0; k < std::min(steps, 5); ++k) expect_wheels(run_behaviour(b, m, rm, rng), spec_wheels(Vec2::polar(1.0, angle)));
}

TEST(Coconut, DegenerateRandomWalksStayFinite) {
  ReferenceModel rm;
  Rng rng(2);
  BehaviourMemory m;
  for (int k = 0; k < 200; ++k) {  // mu = 1 makes every step length infinite without a guard
    const Actuation a = run_behaviour(module(30, {2, 0, 1.0, 1.0}), m, rm, rng);
    EXPECT_TRUE(std::isfinite(a.left_cm) && std::isfinite(a.right_cm));
    EXPECT_GT(m.walk_steps, 0);
  }
}

TEST(Coconut, AStimulusOverridesTheScheme) {
  ReferenceModel rm;
  rm.light = Vec2::polar(1.0, 1.0);
  rm.proximity = Vec2::polar(0.1, -2.0);
  Rng rng(1);
  BehaviourMemory m;
  expect_wheels(run_behaviour(module(32, {1, 30}), m, rm, rng), spec_wheels(rm.light - rm.proximity * 5.0));
  expect_wheels(run_behaviour(module(33, {2, 0, 2.0, 0.5}), m, rm, rng), spec_wheels(-rm.light - rm.proximity * 5.0));
  // Attraction: att (truncated) times A(att): grows with att^2.
  rm.rab_steps[0] = Vec2::polar(0.05, 0.7);  // one buffered step holds the whole sum
  expect_wheels(run_behaviour(module(34, {3.9, 0}), m, rm, rng), spec_wheels(rm.attraction_sum() * 9.0 - rm.proximity * 6.0));
}

// Maple's actions have their own laws (the BT branch's): maple_behaviours_test.cpp.

TEST(Flavours, EveryFlavoursConditionsAreChocolates) {
  ReferenceModel rm;
  rm.ground = 0.0;
  rm.ground_demiurge = 0.0;  // Coconut's read Demiurge's RM3.0 filter (ground_filter_demiurge_test)
  rm.neighbours = 4;
  for (const int base : {10, 20, 30, 40, 50}) {
    for (int digit = 0; digit <= 5; ++digit) {
      Rng a(9), b(9);
      const ModuleInstance chocolate = module(10 + digit, {digit >= 3 && digit <= 4 ? 3.0 : 0.6, 2.0});
      ModuleInstance other = chocolate;
      other.id = base + digit;
      for (int k = 0; k < 50; ++k) EXPECT_EQ(check_condition(chocolate, rm, a), check_condition(other, rm, b));
    }
  }
}

}  // namespace
}  // namespace sd
