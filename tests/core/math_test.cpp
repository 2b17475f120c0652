// core/math.hpp: the simulator's own elementary functions must stay within 2 units in the last
// place of glibc's (which is within 1 of the true value), keep C's special values, and give
// the same bits whichever code path glibc would have picked (checked end to end in
// tests/workflow/cross_cpu_test.cpp).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>

#include "core/math.hpp"
#include "core/rng.hpp"

namespace sd {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

/// Units in the last place between a and b (same sign, finite).
std::uint64_t ulps(double a, double b) {
  if (a == b) return 0;
  auto key = [](double v) {  // doubles ordered as integers
    const auto bits = std::bit_cast<std::int64_t>(v);
    return bits < 0 ? std::numeric_limits<std::int64_t>::min() - bits : bits;
  };
  const std::int64_t d = key(a) - key(b);
  return static_cast<std::uint64_t>(d < 0 ? -d : d);
}

/// Largest ulp distance of f from reference over n arguments drawn uniformly in [lo, hi).
template <typename F, typename G>
std::uint64_t worst_ulps(F f, G reference, double lo, double hi, int n = 200000) {
  Rng rng(7);
  std::uint64_t worst = 0;
  for (int i = 0; i < n; ++i) {
    const double x = rng.uniform(lo, hi);
    worst = std::max(worst, ulps(f(x), reference(x)));
  }
  return worst;
}

TEST(Math, SinAndCosAreWithinTwoUlpsOfLibm) {
  auto s = [](double x) { return math::sin(x); };
  auto c = [](double x) { return math::cos(x); };
  auto ls = [](double x) { return std::sin(x); };
  auto lc = [](double x) { return std::cos(x); };
  for (const double range : {0.7, 3.2, 7.0, 100.0, 1e5}) {
    EXPECT_LE(worst_ulps(s, ls, -range, range), 2u) << range;
    EXPECT_LE(worst_ulps(c, lc, -range, range), 2u) << range;
  }
}

TEST(Math, SinCosPartsEqualSinAndCosAndKeepTheQuadrants) {
  for (int k = -8; k <= 8; ++k) {
    const double x = k * std::numbers::pi / 4 + 0.1;
    const math::SinCos sc = math::sincos(x);
    EXPECT_EQ(sc.sin, math::sin(x));
    EXPECT_EQ(sc.cos, math::cos(x));
    EXPECT_NEAR(sc.sin, std::sin(x), 1e-15) << k;
    EXPECT_NEAR(sc.cos, std::cos(x), 1e-15) << k;
  }
  EXPECT_EQ(math::sin(0.0), 0.0);
  EXPECT_TRUE(std::signbit(math::sin(-0.0)));
  EXPECT_EQ(math::cos(0.0), 1.0);
  EXPECT_TRUE(std::isnan(math::sin(kInf)));
  EXPECT_TRUE(std::isnan(math::cos(std::nan(""))));
  EXPECT_NEAR(math::tan(std::numbers::pi / 5), std::tan(std::numbers::pi / 5), 1e-15);
}

TEST(Math, ExpIsWithinTwoUlpsOfLibmFromUnderflowToOverflow) {
  auto e = [](double x) { return math::exp(x); };
  auto le = [](double x) { return std::exp(x); };
  EXPECT_LE(worst_ulps(e, le, -1.0, 1.0), 2u);
  EXPECT_LE(worst_ulps(e, le, -700.0, 700.0), 2u);
  EXPECT_LE(worst_ulps(e, le, -745.0, -708.0, 20000), 2u);  // subnormal results
  EXPECT_EQ(math::exp(0.0), 1.0);
  EXPECT_EQ(math::exp(710.0), kInf);
  EXPECT_EQ(math::exp(-750.0), 0.0);
  EXPECT_EQ(math::exp(-kInf), 0.0);
  EXPECT_EQ(math::exp(kInf), kInf);
  EXPECT_TRUE(std::isnan(math::exp(std::nan(""))));
}

TEST(Math, LogIsWithinTwoUlpsOfLibmIncludingSubnormals) {
  auto l = [](double x) { return math::log(x); };
  auto ll = [](double x) { return std::log(x); };
  EXPECT_LE(worst_ulps(l, ll, 1e-9, 1.0), 2u);
  EXPECT_LE(worst_ulps(l, ll, 0.5, 2.0), 2u);
  EXPECT_LE(worst_ulps(l, ll, 1.0, 1e300), 2u);
  EXPECT_LE(worst_ulps([](double u) { return math::log(u * 0x1p-1060); }, [](double u) { return std::log(u * 0x1p-1060); },
                       0.01, 1.0, 20000),
            2u);
  EXPECT_EQ(math::log(1.0), 0.0);
  EXPECT_EQ(math::log(0.0), -kInf);
  EXPECT_EQ(math::log(kInf), kInf);
  EXPECT_TRUE(std::isnan(math::log(-1.0)));
  EXPECT_TRUE(std::isnan(math::log(std::nan(""))));
}

TEST(Math, AtanAndAtan2AreWithinTwoUlpsOfLibm) {
  auto a = [](double x) { return math::atan(x); };
  auto la = [](double x) { return std::atan(x); };
  EXPECT_LE(worst_ulps(a, la, -1.0, 1.0), 2u);
  EXPECT_LE(worst_ulps(a, la, -1e6, 1e6), 2u);
  Rng rng(11);
  std::uint64_t worst = 0;
  for (int i = 0; i < 200000; ++i) {
    const double y = rng.uniform(-2.0, 2.0), x = rng.uniform(-2.0, 2.0);
    worst = std::max(worst, ulps(math::atan2(y, x), std::atan2(y, x)));
  }
  EXPECT_LE(worst, 2u);
}

TEST(Math, Atan2KeepsCsConventionsForZerosAndInfinities) {
  const double pi = std::numbers::pi;
  for (const double y : {0.0, -0.0, 1.0, -1.0, kInf, -kInf})
    for (const double x : {0.0, -0.0, 1.0, -1.0, kInf, -kInf}) {
      const double mine = math::atan2(y, x), libm = std::atan2(y, x);
      EXPECT_EQ(std::signbit(mine), std::signbit(libm)) << y << " " << x;
      EXPECT_NEAR(mine, libm, 1e-15) << y << " " << x;
    }
  EXPECT_EQ(math::atan2(0.0, 0.0), 0.0);  // ARGoS' angle of the zero vector
  EXPECT_EQ(math::atan2(1.0, 0.0), math::atan2(5.0, 0.0));
  EXPECT_NEAR(math::atan2(-1.0, -1.0), -3 * pi / 4, 1e-15);
  EXPECT_TRUE(std::isnan(math::atan2(std::nan(""), 1.0)));
}

TEST(Math, PowIsExpOfTheLogForPositiveBases) {
  EXPECT_NEAR(math::pow(0.25, 0.5), 0.5, 1e-16);
  EXPECT_NEAR(math::pow(10.0, -4.0), 1e-4, 1e-19);
  EXPECT_NEAR(math::pow(0.3, 1.0 / 7.0), std::pow(0.3, 1.0 / 7.0), 1e-15);
  EXPECT_TRUE(std::isnan(math::pow(-2.0, 2.0)));
}

}  // namespace
}  // namespace sd
