#pragma once
// The five numbers, whiskers, notches and outliers of a box plot, as R's boxplot.stats.
#include <cstddef>
#include <span>
#include <vector>

namespace sd::statistics {

struct BoxStats {
  std::size_t n = 0;
  double min = 0, q1 = 0, median = 0, q3 = 0, max = 0;  // fivenum(): Tukey's hinges
  double whisker_low = 0, whisker_high = 0;  // most extreme values within 1.5 IQR of the hinges
  double notch_low = 0, notch_high = 0;      // median -/+ 1.58 IQR / sqrt(n)
  std::vector<double> outliers;              // sorted ascending (R keeps input order)
};
/// R's boxplot.stats(x) (coef = 1.5, do.conf = TRUE, do.out = TRUE), with fivenum's min and
/// max kept besides the whiskers. A constant sample has every number equal and no outlier.
/// Throws std::invalid_argument on empty or non-finite input.
BoxStats box_stats(std::span<const double> x);

}  // namespace sd::statistics
