#pragma once
// The unpaired Wilcoxon rank-sum (Mann-Whitney) test, as R's wilcox.test(x, y): the report's
// comparison of two conditions on one mission.
#include <span>

namespace sd::statistics {

struct RankSumTest {
  double statistic = 0.0;  // W: sum of the ranks of x minus nx(nx+1)/2
  double p_value = 1.0;    // two-sided; NaN when every value of x and y is the same (as R)
  bool exact = false;      // exact distribution (nx < 50, ny < 50, no ties)
};
/// Unpaired two-sided Wilcoxon rank-sum test with R's defaults (correct = TRUE, exact = NULL):
/// exact p-value when nx < 50, ny < 50 and there are no ties, else the normal approximation
/// with tie and continuity correction. Throws std::invalid_argument when x or y is empty or
/// holds a NaN.
RankSumTest wilcoxon_rank_sum(std::span<const double> x, std::span<const double> y);

/// P(W <= q) for the rank-sum statistic of samples of sizes m and n (R pwilcox).
/// Exact counting in doubles; cost O(m^2 n^2), meant for m, n < 50. Throws unless m, n >= 1.
double pwilcox(double q, int m, int n);

}  // namespace sd::statistics
