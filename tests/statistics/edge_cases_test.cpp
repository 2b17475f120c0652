// The edge cases each function documents (empty input, ties, zero variance), one behaviour each:
// empty input throws everywhere instead of giving NaN in one place and 0 in another.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "statistics/box_stats.hpp"
#include "statistics/correlation.hpp"
#include "statistics/descriptive.hpp"
#include "statistics/expected_ranks.hpp"
#include "statistics/friedman.hpp"
#include "statistics/r_matrices.hpp"
#include "statistics/rank_sum.hpp"
#include "statistics/ranks.hpp"
#include "statistics/signed_rank.hpp"
#include "statistics/stouffer.hpp"
#include "statistics/paired_t.hpp"
#include "statistics/welch.hpp"

using namespace sd::statistics;
using namespace sd::statistics::testing;

namespace {

const std::vector<double> kEmpty;
const double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

TEST(statistics_EdgeCases, EmptyInputThrowsInsteadOfGivingAValue) {
  EXPECT_THROW(mean(kEmpty), std::invalid_argument);
  EXPECT_THROW(median(kEmpty), std::invalid_argument);
  EXPECT_THROW(sample_variance(kEmpty), std::invalid_argument);
  EXPECT_THROW(sample_standard_deviation(kEmpty), std::invalid_argument);
  EXPECT_THROW(box_stats(kEmpty), std::invalid_argument);
  EXPECT_THROW(wilcoxon_rank_sum(kEmpty, std::vector<double>{1}), std::invalid_argument);
  EXPECT_THROW(wilcoxon_signed_rank(kEmpty, kEmpty), std::invalid_argument);
  EXPECT_THROW(friedman_test(CostMatrix(0, 3)), std::invalid_argument);
  EXPECT_THROW(expected_ranks({}, {}), std::invalid_argument);
}

TEST(statistics_EdgeCases, EmptyInputHasNoRanksAndNoTies) {
  EXPECT_TRUE(average_ranks(kEmpty).empty());
  EXPECT_EQ(tie_term(kEmpty), 0.0);
}

TEST(statistics_EdgeCases, OneValue) {
  const std::vector<double> one{2.5};
  EXPECT_EQ(mean(one), 2.5);
  EXPECT_EQ(median(one), 2.5);
  // A spread needs two values: R gives NA, here it is an error like the empty sample's.
  EXPECT_THROW(sample_variance(one), std::invalid_argument);
  EXPECT_THROW(sample_standard_deviation(one), std::invalid_argument);
}

TEST(statistics_EdgeCases, NaNPropagatesThroughMeanAndMedian) {
  // R: mean(c(1, NaN, 3)) and median(c(1, NA, 3)) are not numbers.
  const std::vector<double> x{1, kNaN, 3};
  EXPECT_TRUE(std::isnan(mean(x)));
  EXPECT_TRUE(std::isnan(median(x)));
}

TEST(statistics_EdgeCases, TiesShareTheirAverageRankAndCountInTheTieTerm) {
  const std::vector<double> all_tied{7, 7, 7, 7};
  EXPECT_EQ(average_ranks(all_tied), (std::vector<double>{2.5, 2.5, 2.5, 2.5}));
  EXPECT_EQ(tie_term(all_tied), 60.0);  // 4^3 - 4
  // groups of 2 and 3: (8 - 2) + (27 - 3)
  EXPECT_EQ(tie_term(std::vector<double>{1, 3, 1, 3, 3}), 30.0);
  EXPECT_EQ(tie_term(std::vector<double>{1, 2, 3}), 0.0);
}

TEST(statistics_EdgeCases, ZeroVariance) {
  const std::vector<double> constant{4, 4, 4};
  EXPECT_EQ(sample_variance(constant), 0.0);
  EXPECT_EQ(sample_standard_deviation(constant), 0.0);
  const BoxStats b = box_stats(constant);
  EXPECT_EQ(b.whisker_low, 4.0);
  EXPECT_EQ(b.whisker_high, 4.0);
  EXPECT_EQ(b.notch_low, 4.0);
  EXPECT_EQ(b.notch_high, 4.0);
  EXPECT_TRUE(b.outliers.empty());
  // Spearman's rho of a constant sample is undefined (R: NA with a warning).
  EXPECT_TRUE(std::isnan(spearman_rho(constant, std::vector<double>{1, 2, 3})));
  // One constant sample is fine for Welch: only its own variance is 0.
  const WelchTest one_constant = welch_t_test(constant, std::vector<double>{1, 2, 3});
  EXPECT_TRUE(std::isfinite(one_constant.statistic));
  EXPECT_GT(one_constant.p_value, 0.0);
}

TEST(statistics_EdgeCases, RankTestsWithEverythingTied) {
  // R: wilcox.test(c(1, 1), c(1, 1))$p.value is NaN.
  EXPECT_TRUE(std::isnan(wilcoxon_rank_sum(std::vector<double>{1, 1}, std::vector<double>{1, 1}).p_value));
  // Every row a complete tie: the Friedman statistic is 0/0, and so is its p-value.
  const FriedmanTest f = friedman_test(matrix(3, 3, std::vector<double>(9, 1.0)));
  EXPECT_TRUE(std::isnan(f.statistic));
  EXPECT_TRUE(std::isnan(f.p_value));
  EXPECT_EQ(f.rank_sums, (std::vector<double>{6, 6, 6}));
  // Every paired difference 0: no signed-rank test (R stops too); mismatched lengths likewise.
  EXPECT_THROW(wilcoxon_signed_rank(std::vector<double>{1, 2}, std::vector<double>{1, 2}), std::invalid_argument);
  EXPECT_THROW(wilcoxon_signed_rank(std::vector<double>{1, 2}, std::vector<double>{1}), std::invalid_argument);
}

TEST(statistics_EdgeCases, ConoverCriticalDifference) {
  // R: qt(0.975, 15) * sqrt(2 * (6 * sum(r^2) - sum(colSums(r)^2)) / 15) on y1's row ranks
  EXPECT_NEAR(conover_critical_difference(y1(), 0.05), 2.461185937786083, 1e-12);
  EXPECT_NEAR(conover_critical_difference(y3(), 0.05), 6.9680261327127928, 1e-12);
  // Every row ranks the columns alike: no spread, so any difference in rank sums counts.
  EXPECT_EQ(conover_critical_difference(matrix(3, 3, {1, 2, 3, 1, 2, 3, 1, 2, 3}), 0.05), 0.0);
  // One row: no degrees of freedom to estimate the spread from.
  EXPECT_TRUE(std::isnan(conover_critical_difference(matrix(1, 3, {1, 2, 3}), 0.05)));
  EXPECT_THROW(conover_critical_difference(matrix(3, 1, {1, 2, 3}), 0.05), std::invalid_argument);
}

TEST(statistics_EdgeCases, ExpectedRanksWithOneBlockHaveNoCriticalDifference) {
  // One mission: the test cannot reject (p = 0.37 for k = 3) and there is no CD to give.
  const ExpectedRanks e = expected_ranks({{3, 2, 1}}, {false}, 0.95);
  EXPECT_EQ(e.mean_ranks, (std::vector<double>{3, 2, 1}));
  EXPECT_FALSE(e.critical_difference.has_value());
}

TEST(statistics_EdgeCases, StoufferCombinesScoresAndRefusesNone) {
  // R: z <- sum(c(1, 1, 1, 1)) / sqrt(4); 2 * pnorm(-abs(z)) -> 2, 0.045500263896358417
  const StoufferTest s = stouffer_z(std::vector<double>{1, 1, 1, 1});
  EXPECT_EQ(s.z, 2.0);
  EXPECT_NEAR(s.p_value, 0.045500263896358417, 1e-15);
  const StoufferTest balanced = stouffer_z(std::vector<double>{1.5, -1.5});
  EXPECT_EQ(balanced.z, 0.0);
  EXPECT_EQ(balanced.p_value, 1.0);
  EXPECT_THROW(stouffer_z(kEmpty), std::invalid_argument);
}

// R: t.test(extra ~ group, data = sleep, paired = TRUE) -> t = -4.0621, df = 9, p-value = 0.002833;
// qnorm(0.002833 / 2) = -2.985.
TEST(statistics_PairedT, MatchesRsSleepData) {
  const std::vector<double> one{0.7, -1.6, -0.2, -1.2, -0.1, 3.4, 3.7, 0.8, 0.0, 2.0};
  const std::vector<double> two{1.9, 0.8, 1.1, 0.1, -0.1, 4.4, 5.5, 1.6, 4.6, 3.4};
  const sd::statistics::PairedTest t = sd::statistics::paired_t_test(one, two);
  EXPECT_NEAR(t.statistic, -4.062128, 1e-6);
  EXPECT_EQ(t.df, 9.0);
  EXPECT_NEAR(t.p_value, 0.002832890, 1e-8);
  EXPECT_NEAR(t.z, -2.985312, 1e-5);
  const sd::statistics::PairedTest back = sd::statistics::paired_t_test(two, one);
  EXPECT_NEAR(back.z, 2.985312, 1e-5);
}

TEST(statistics_PairedT, EdgeCasesAreSaid) {
  const std::vector<double> a{1, 2, 3}, b{1, 2, 3}, shifted{2, 3, 4};
  EXPECT_EQ(sd::statistics::paired_t_test(a, b).statistic, 0.0);
  EXPECT_EQ(sd::statistics::paired_t_test(a, b).p_value, 1.0);
  EXPECT_TRUE(std::isinf(sd::statistics::paired_t_test(shifted, a).z));
  EXPECT_GT(sd::statistics::paired_t_test(shifted, a).z, 0.0);
  EXPECT_THROW(sd::statistics::paired_t_test(std::vector<double>{1}, std::vector<double>{2}), std::invalid_argument);
  EXPECT_THROW(sd::statistics::paired_t_test(a, std::vector<double>{1, 2}), std::invalid_argument);
  EXPECT_THROW(sd::statistics::paired_t_test(a, std::vector<double>{1, NAN, 3}), std::invalid_argument);
}
