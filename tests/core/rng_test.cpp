// The run's generator: the batched coarse draws the sensors use must be the very values the
// one-at-a-time draws give, whatever is left over from earlier calls.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/rng.hpp"

namespace sd {
namespace {

TEST(Rng, BatchedCoarseUniformsEqualOneAtATimeDraws) {
  Rng single(42), batched(42);
  // Batch sizes that start and end at every offset within a 64-bit word (3 draws per word),
  // with full draws in between, as the sensors interleave them.
  for (const int n : {1, 3, 8, 2, 5, 8, 3, 1, 7}) {
    std::array<double, 8> out{};
    batched.coarse_uniforms(-0.05, 0.05, out.data(), n);
    for (int k = 0; k < n; ++k) ASSERT_EQ(out[static_cast<std::size_t>(k)], single.coarse_uniform(-0.05, 0.05)) << n << " " << k;
    ASSERT_EQ(batched.next(), single.next());
  }
}

TEST(Rng, CoarseUniformsTakeThreeChunksOf21BitsFromEachWord) {
  Rng words(9), draws(9);
  for (int w = 0; w < 4; ++w) {
    std::uint64_t bits = words.next();
    for (int chunk = 0; chunk < 3; ++chunk, bits >>= 21)
      ASSERT_EQ(draws.coarse_uniform(-2.0, 2.0), -2.0 + 4.0 * 0x1.0p-21 * static_cast<double>(bits & 0x1fffff)) << w << " " << chunk;
  }
}

TEST(Rng, CoarseUniformsStayInTheirIntervalAndFillIt) {
  Rng rng(3);
  std::array<double, 8> out{};
  double lo = 1.0, hi = -1.0, sum = 0.0;
  constexpr int kBatches = 20000;
  for (int b = 0; b < kBatches; ++b) {
    rng.coarse_uniforms(-0.5, 0.5, out.data(), 8);
    for (const double v : out) {
      ASSERT_GE(v, -0.5);
      ASSERT_LT(v, 0.5);
      lo = std::min(lo, v);
      hi = std::max(hi, v);
      sum += v;
    }
  }
  EXPECT_LT(lo, -0.499);
  EXPECT_GT(hi, 0.499);
  EXPECT_NEAR(sum / (8.0 * kBatches), 0.0, 0.005);  // sd of the mean: 0.29 / sqrt(160000) = 0.0007
}

// The ziggurat's normals against the normal distribution: the Kolmogorov-Smirnov distance
// over the whole line, and the frequencies of the regions each of its paths serves (the
// layers' rectangles, the wedges, the tail beyond r = 3.654).
TEST(Rng, ZigguratNormalsFollowTheStandardNormalDistribution) {
  Rng rng(2024);
  constexpr int kDraws = 400000;
  std::vector<double> z(kDraws);
  double sum = 0.0, sum_sq = 0.0;
  for (double& v : z) {
    v = rng.normal();
    sum += v;
    sum_sq += v * v;
  }
  EXPECT_NEAR(sum / kDraws, 0.0, 4.0 / std::sqrt(kDraws));
  EXPECT_NEAR(sum_sq / kDraws, 1.0, 4.0 * std::sqrt(2.0 / kDraws));
  std::sort(z.begin(), z.end());
  double ks = 0.0;
  for (int i = 0; i < kDraws; ++i) {
    const double cdf = 0.5 * std::erfc(-z[static_cast<std::size_t>(i)] / std::sqrt(2.0));
    ks = std::max({ks, std::abs(cdf - static_cast<double>(i) / kDraws), std::abs(cdf - static_cast<double>(i + 1) / kDraws)});
  }
  EXPECT_LT(ks, 1.63 / std::sqrt(kDraws));  // the 1 % critical value
  auto beyond = [&](double t) {
    return static_cast<double>(std::count_if(z.begin(), z.end(), [t](double v) { return std::abs(v) > t; }));
  };
  for (const double t : {0.5, 2.0, 3.0, 3.654152885361009, 4.0}) {
    const double p = std::erfc(t / std::sqrt(2.0));  // P(|Z| > t)
    EXPECT_NEAR(beyond(t), p * kDraws, 5.0 * std::sqrt(p * kDraws) + 1.0) << t;
  }
  EXPECT_NEAR(static_cast<double>(std::count_if(z.begin(), z.end(), [](double v) { return v < 0.0; })), kDraws / 2.0,
              4.0 * std::sqrt(kDraws / 4.0));
}

TEST(Rng, NormalsDependOnlyOnTheGeneratorState) {
  Rng a(5), b(5);
  for (int i = 0; i < 1000; ++i) a.normal();
  const Rng::State saved = a.state();
  std::vector<double> first(100);
  for (double& v : first) v = a.normal();
  b.set_state(saved);
  for (const double v : first) EXPECT_EQ(b.normal(), v);
}

}  // namespace
}  // namespace sd
