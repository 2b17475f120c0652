// Coconut's and Arlequin's floor conditions (ids 30-32 and 50-52) read Demiurge's RM3.0 ground
// filter (10 steps, tests/robot/ground_filter_demiurge_test), the only code base that has
// them; Chocolate's (10-12) RM1.x's.
#include <gtest/gtest.h>

#include "module_test_helpers.hpp"
#include "modules/conditions.hpp"

namespace sd {
namespace {

using test::module;

TEST(DemiurgeFloorConditions, ReadDemiurgesGroundFilter) {
  for (const int base : {30, 50}) {
    SCOPED_TRACE(base);
    ReferenceModel rm;
    rm.ground = 0.5;  // RM1.x: gray
    rm.ground_demiurge = 0.0;  // Demiurge's RM3.0: black
    Rng rng(1);
    EXPECT_TRUE(check_condition(module(base, {1.0}), rm, rng));
    EXPECT_FALSE(check_condition(module(base + 1, {1.0}), rm, rng));
    EXPECT_TRUE(check_condition(module(11, {1.0}), rm, rng));
    rm.ground_demiurge = 1.0;
    EXPECT_TRUE(check_condition(module(base + 2, {1.0}), rm, rng));
    EXPECT_FALSE(check_condition(module(12, {1.0}), rm, rng));
    rm.ground_demiurge = 0.5;
    rm.ground = 0.0;
    EXPECT_TRUE(check_condition(module(base + 1, {1.0}), rm, rng));
    EXPECT_FALSE(check_condition(module(base, {1.0}), rm, rng));
    EXPECT_TRUE(check_condition(module(10, {1.0}), rm, rng));
  }
}

}  // namespace
}  // namespace sd
