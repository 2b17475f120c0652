// TuttiFrutti's floor conditions (ids 20-22) read the same filter as Chocolate's (10-12): the
// RM3.0 of TuttiFrutti's code base (demiurge-epuck-dao branch tuttifrutti) counts a sample black
// below 0.03 and white above 0.85, as RM1.2, so a noisy black floor can read gray for both.
#include <gtest/gtest.h>

#include "module_test_helpers.hpp"
#include "modules/conditions.hpp"

namespace sd {
namespace {

using test::module;

TEST(TuttiFloorConditions, ReadTheRm12GroundFilter) {
  ReferenceModel rm;
  rm.ground = 0.5;            // gray: e.g. noisy black samples above 0.03
  rm.ground_demiurge = 0.0;   // Demiurge's filter (Coconut, Arlequin) is not TuttiFrutti's
  Rng rng(1);
  EXPECT_FALSE(check_condition(module(20, {1.0}), rm, rng));
  EXPECT_TRUE(check_condition(module(21, {1.0}), rm, rng));
  rm.ground = 0.0;
  EXPECT_TRUE(check_condition(module(20, {1.0}), rm, rng));
  EXPECT_FALSE(check_condition(module(21, {1.0}), rm, rng));
  EXPECT_FALSE(check_condition(module(22, {1.0}), rm, rng));
  rm.ground = 1.0;
  rm.ground_demiurge = 0.5;
  EXPECT_TRUE(check_condition(module(22, {1.0}), rm, rng));
  EXPECT_FALSE(check_condition(module(21, {1.0}), rm, rng));
}

}  // namespace
}  // namespace sd
