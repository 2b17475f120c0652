// The branch-free helpers must give exactly what the plain conditionals give, since the
// simulator swapped one for the other without changing any result.
#include "core/branchless.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/rng.hpp"

namespace sd {
namespace {

TEST(Branchless, SelectPicksByCondition) {
  EXPECT_EQ(select(true, 1.5, -2.0), 1.5);
  EXPECT_EQ(select(false, 1.5, -2.0), -2.0);
  EXPECT_TRUE(std::signbit(select(true, -0.0, 0.0)));
  EXPECT_FALSE(std::signbit(select(false, -0.0, 0.0)));
  EXPECT_TRUE(std::isnan(select(true, std::numeric_limits<double>::quiet_NaN(), 0.0)));
  EXPECT_EQ(select(false, std::numeric_limits<double>::quiet_NaN(), 3.0), 3.0);
}

TEST(Branchless, Max0AndClamp01MatchThePlainConditionalsBitForBit) {
  Rng rng(7);
  for (int k = 0; k < 100000; ++k) {
    // Mostly around the bounds, where readings with noise sit, and some far from them.
    const double v = k % 10 == 0 ? rng.uniform(-1e6, 1e6) : rng.uniform(-0.2, 1.2);
    const double plain_max = v > 0.0 ? v : 0.0;
    const double plain_clamp = v < 0.0 ? 0.0 : (v > 1.0 ? 1.0 : v);
    ASSERT_EQ(max0(v), plain_max) << v;
    ASSERT_EQ(clamp01(v), plain_clamp) << v;
  }
  EXPECT_EQ(max0(-0.0), 0.0);
  EXPECT_FALSE(std::signbit(max0(-0.0)));
  EXPECT_EQ(max0(std::numeric_limits<double>::denorm_min()), std::numeric_limits<double>::denorm_min());
  EXPECT_EQ(max0(-std::numeric_limits<double>::denorm_min()), 0.0);
  EXPECT_EQ(clamp01(1.0), 1.0);
  EXPECT_EQ(clamp01(std::nextafter(1.0, 2.0)), 1.0);
}

}  // namespace
}  // namespace sd
