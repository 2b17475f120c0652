#pragma once
// The statistics of the experiments report: per-mission comparisons of two conditions
// (Wilcoxon rank-sum), box plots of the design scores, and the Friedman test across missions;
// and the agreement of two simulators' scores (Welch's t-test, sign test, Spearman's rho) that
// the calibration against ARGoS checks.
// Each function reproduces an R function (named in its comment) so that the report can be
// checked against R; the Friedman rank arithmetic is shared with the race (design/statistics).
#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace sd::experiments {

struct RankSumTest {
  double statistic = 0.0;  // W: sum of the ranks of x minus nx(nx+1)/2
  double p_value = 1.0;    // two-sided; NaN when every value of x and y is the same (as R)
  bool exact = false;      // exact distribution (nx < 50, ny < 50, no ties)
};
/// Unpaired two-sided Wilcoxon rank-sum (Mann-Whitney) test as R's wilcox.test(x, y) with its
/// defaults (correct = TRUE, exact = NULL): exact p-value when nx < 50, ny < 50 and there are
/// no ties, else the normal approximation with tie and continuity correction.
/// Throws std::invalid_argument when x or y is empty or holds a NaN.
RankSumTest wilcoxon_rank_sum(std::span<const double> x, std::span<const double> y);

/// P(W <= q) for the rank-sum statistic of samples of sizes m and n (R pwilcox).
/// Exact counting in doubles; cost O(m^2 n^2), meant for m, n < 50.
double pwilcox(double q, int m, int n);

struct BoxStats {
  std::size_t n = 0;
  double min = 0, q1 = 0, median = 0, q3 = 0, max = 0;  // fivenum(): Tukey's hinges
  double whisker_low = 0, whisker_high = 0;  // most extreme values within 1.5 IQR of the hinges
  double notch_low = 0, notch_high = 0;      // median -/+ 1.58 IQR / sqrt(n)
  std::vector<double> outliers;              // sorted ascending (R keeps input order)
};
/// R's boxplot.stats(x) (coef = 1.5, do.conf = TRUE, do.out = TRUE), with fivenum's min and
/// max kept besides the whiskers. Throws std::invalid_argument on empty or non-finite input.
BoxStats box_stats(std::span<const double> x);

/// R's median(x). Throws std::invalid_argument on empty input.
double median(std::span<const double> x);

struct ExpectedRanks {
  double statistic = 0.0;  // Friedman chi-squared with tie correction; NaN if every block is tied
  double p_value = 1.0;
  int df = 0;                     // conditions - 1
  std::vector<double> mean_ranks;  // per condition, 1 = best
  std::optional<double> critical_difference;  // on mean ranks, only when the test rejects
                                              // (0 when all blocks rank the conditions alike)
};
/// Friedman test across missions: values[block][condition], blocks are missions, each value a
/// condition's median score on that mission. A block with higher_is_better[block] is negated
/// first, so that rank 1 is the best condition in every block; statistic and p-value then equal
/// R's friedman.test on the sign-adjusted matrix. When p < 1 - confidence the critical
/// difference of the Conover post-hoc test is given on the scale of the mean ranks: two
/// conditions whose mean ranks differ by more than it differ significantly:
///   CD = qt(1 - alpha/2, (b-1)(k-1)) * sqrt(2 (b A - sum_j R_j^2) / ((b-1)(k-1))) / b,
/// alpha = 1 - confidence, b blocks, k conditions, A the sum of the squared within-block ranks,
/// R_j the rank sums (irace's / PMCMR's Conover test on rank sums, divided by b).
/// Throws std::invalid_argument unless the matrix is rectangular, finite, with >= 1 block and
/// >= 2 conditions, and higher_is_better has one entry per block.
ExpectedRanks expected_ranks(const std::vector<std::vector<double>>& values,
                             const std::vector<bool>& higher_is_better, double confidence = 0.95);

/// R's mean(x) and sd(x) (n - 1 in the denominator). x must hold at least 1 and 2 values.
double mean(std::span<const double> x);
double sample_standard_deviation(std::span<const double> x);

struct WelchTest {
  double statistic = 0.0;  // t = (mean(x) - mean(y)) / sqrt(var(x)/nx + var(y)/ny)
  double df = 0.0;         // Welch-Satterthwaite degrees of freedom
  double p_value = 1.0;    // two-sided
};
/// R's t.test(x, y) (Welch, two-sided). When both samples are constant the test is undefined
/// in R; here p is 1 if the constants are equal and 0 otherwise, so that two simulators that
/// agree exactly pass and two that disagree exactly fail.
/// Throws std::invalid_argument unless both samples have at least 2 finite values.
WelchTest welch_t_test(std::span<const double> x, std::span<const double> y);

/// R's binom.test(successes, trials, 0.5)$p.value: the two-sided sign test (1 when trials is 0).
double sign_test_p_value(int successes, int trials);

/// R's cor(x, y, method = "spearman"): Pearson's correlation of the average ranks.
/// NaN when either sample is constant. Throws std::invalid_argument unless x and y have the
/// same size >= 2.
double spearman_rho(std::span<const double> x, std::span<const double> y);

}  // namespace sd::experiments
