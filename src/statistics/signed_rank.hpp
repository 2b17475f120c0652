#pragma once
// The paired Wilcoxon signed-rank test, as R's wilcox.test(x, y, paired = TRUE, conf.int = TRUE):
// the race's test when two configurations are left (irace 3.5 R/race.R aux_friedman).
#include <span>

namespace sd::statistics {

struct SignedRankTest {
  double statistic = 0.0;  // V: sum of the ranks of the positive differences
  double p_value = 1.0;    // two-sided
  double estimate = 0.0;   // Hodges-Lehmann (pseudo)median of x - y
  bool exact = false;      // exact distribution (n < 50, no ties, no zeros)
};
/// Paired Wilcoxon signed-rank test of x - y: zero differences are dropped (R's default), then
/// exact p for n < 50 without ties or zeros, else the normal approximation with continuity and
/// tie correction. In the approximate case the estimate is the root of the uncorrected
/// standardised statistic, found by bisection (R uses uniroot, tol 1e-4; the race uses only its
/// sign). Throws std::invalid_argument when x and y differ in length or every difference is 0
/// (also on empty input).
SignedRankTest wilcoxon_signed_rank(std::span<const double> x, std::span<const double> y);

/// P(V <= q) for the signed-rank statistic of n observations (R psignrank). Throws when n < 0.
double psignrank(double q, int n);

}  // namespace sd::statistics
