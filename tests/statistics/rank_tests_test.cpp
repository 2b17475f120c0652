// The rank tests the race and the report share. Expected values computed with R 4.2.2 (irace 3.5
// installed); each literal names its R call.
#include <gtest/gtest.h>

#include "statistics/friedman.hpp"
#include "statistics/r_matrices.hpp"
#include "statistics/ranks.hpp"
#include "statistics/signed_rank.hpp"

using namespace sd::statistics;
using namespace sd::statistics::testing;

TEST(statistics_RankTests, AverageRanksMatchR) {
  // R: rank(c(3,1,4,1,5,9,2,6,5,3,5))
  const std::vector<double> x{3, 1, 4, 1, 5, 9, 2, 6, 5, 3, 5};
  const std::vector<double> expected{4.5, 1.5, 6, 1.5, 8, 11, 3, 10, 8, 4.5, 8};
  EXPECT_EQ(average_ranks(x), expected);
}

TEST(statistics_RankTests, FriedmanWithoutTies) {
  // R: friedman.test(y) -> 17, 0.00070674239233702875; colSums(t(apply(y,1,rank))) -> 13 6 24 17
  const FriedmanTest f = friedman_test(y1());
  EXPECT_NEAR(f.statistic, 17.0, 1e-12);
  EXPECT_NEAR(f.p_value, 0.00070674239233702875, 1e-15);
  EXPECT_EQ(f.rank_sums, (std::vector<double>{13, 6, 24, 17}));
}

TEST(statistics_RankTests, FriedmanWithTies) {
  // R: friedman.test(y2) -> 11.833333333333334, 0.018634646635166056; rank sums 10.5 12 11.5 19 22
  const FriedmanTest f = friedman_test(y2());
  EXPECT_NEAR(f.statistic, 11.833333333333334, 1e-12);
  EXPECT_NEAR(f.p_value, 0.018634646635166056, 1e-14);
  EXPECT_EQ(f.rank_sums, (std::vector<double>{10.5, 12, 11.5, 19, 22}));
}

TEST(statistics_RankTests, SignedRankDistribution) {
  // R: psignrank(10, 9); psignrank(3, 5); psignrank(40, 12)
  EXPECT_NEAR(psignrank(10, 9), 0.08203125, 1e-15);
  EXPECT_NEAR(psignrank(3, 5), 0.15625, 1e-15);
  EXPECT_NEAR(psignrank(40, 12), 0.54516601562499989, 1e-14);
}

TEST(statistics_RankTests, WilcoxonExact) {
  // R: wilcox.test(x, y, paired=TRUE, conf.int=TRUE) -> V 40, p 0.0390625, estimate 0.46000000000000008
  const std::vector<double> x{1.83, 0.50, 1.62, 2.48, 1.68, 1.88, 1.55, 3.06, 1.30};
  const std::vector<double> y{0.878, 0.647, 0.598, 2.05, 1.06, 1.29, 1.06, 3.14, 1.29};
  const SignedRankTest w = wilcoxon_signed_rank(x, y);
  EXPECT_TRUE(w.exact);
  EXPECT_EQ(w.statistic, 40);
  EXPECT_NEAR(w.p_value, 0.0390625, 1e-15);
  EXPECT_NEAR(w.estimate, 0.46000000000000008, 1e-12);
}

TEST(statistics_RankTests, WilcoxonNormalApproximationWithTies) {
  // R: wilcox.test(x2, y2w, paired=TRUE, conf.int=TRUE) -> V 30, p 0.49459932738312368, estimate -0.49995 (uniroot)
  const std::vector<double> x{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
  const std::vector<double> y{2, 1, 3.5, 3, 7, 5, 9, 8.5, 8, 12, 10, 13};
  const SignedRankTest w = wilcoxon_signed_rank(x, y);
  EXPECT_FALSE(w.exact);
  EXPECT_EQ(w.statistic, 30);
  EXPECT_NEAR(w.p_value, 0.49459932738312368, 1e-14);
  EXPECT_NEAR(w.estimate, -0.5, 1e-3);

  // R: x3 vs y3w (differences with ties) -> V 77, p 0.0031808856350796738, estimate 0.39996 (uniroot)
  const std::vector<double> x3{5.1, 4.9, 6.2, 5.8, 6.0, 5.5, 5.3, 6.1, 5.9, 5.7, 6.3, 5.2};
  const std::vector<double> d{0.5, 0.3, 0.4, -0.1, 0.6, 0.5, 0.2, 0.7, 0.4, 0.5, 0.3, 0.2};
  std::vector<double> y3(12);
  for (std::size_t i = 0; i < 12; ++i) y3[i] = x3[i] - d[i];
  const SignedRankTest w3 = wilcoxon_signed_rank(x3, y3);
  EXPECT_EQ(w3.statistic, 77);
  EXPECT_NEAR(w3.p_value, 0.0031808856350796738, 1e-14);
  EXPECT_NEAR(w3.estimate, 0.4, 1e-3);
}
