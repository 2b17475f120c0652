// TuttiFrutti's floor conditions (ids 20-22) read RM3.0's ground filter, Chocolate's (10-12)
// RM1.x's: on a noisy black floor the two filters disagree (tests/robot/ground_filter_rm3_test).
#include <gtest/gtest.h>

#include "module_test_helpers.hpp"
#include "modules/conditions.hpp"

namespace sd {
namespace {

using test::module;

TEST(TuttiFloorConditions, ReadTheRm3GroundFilter) {
  ReferenceModel rm;
  rm.ground = 0.5;      // RM1.x: gray (noisy black samples above 0.03)
  rm.ground_rm3 = 0.0;  // RM3.0: black
  Rng rng(1);
  EXPECT_TRUE(check_condition(module(20, {1.0}), rm, rng));
  EXPECT_FALSE(check_condition(module(21, {1.0}), rm, rng));
  EXPECT_FALSE(check_condition(module(10, {1.0}), rm, rng));
  EXPECT_TRUE(check_condition(module(11, {1.0}), rm, rng));
  rm.ground = 0.5;
  rm.ground_rm3 = 1.0;
  EXPECT_TRUE(check_condition(module(22, {1.0}), rm, rng));
  EXPECT_FALSE(check_condition(module(12, {1.0}), rm, rng));
  rm.ground_rm3 = 0.5;
  EXPECT_TRUE(check_condition(module(21, {1.0}), rm, rng));
  EXPECT_FALSE(check_condition(module(20, {1.0}), rm, rng));
  EXPECT_FALSE(check_condition(module(22, {1.0}), rm, rng));
}

}  // namespace
}  // namespace sd
