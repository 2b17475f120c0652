#pragma once
// The report's comparison of conditions across missions: Friedman with missions as blocks,
// each condition's mean rank, and Conover's critical difference on the mean-rank scale.
#include <optional>
#include <vector>

namespace sd::statistics {

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
/// difference of the Conover post-hoc test (conover_critical_difference) is given divided by
/// the b blocks, on the scale of the mean ranks: two conditions whose mean ranks differ by more
/// than it differ significantly. None with a single block (no spread to estimate).
/// Throws std::invalid_argument unless the matrix is rectangular, finite, with >= 1 block and
/// >= 2 conditions, and higher_is_better has one entry per block, and confidence in (0, 1).
ExpectedRanks expected_ranks(const std::vector<std::vector<double>>& values,
                             const std::vector<bool>& higher_is_better, double confidence = 0.95);

}  // namespace sd::statistics
