#pragma once
// The paired t-test, as R's t.test(x, y, paired = TRUE): for comparisons made pair by pair (ARGoS'
// run from one start placement against SwarmDesign's mean from the same placement), plus the
// standard normal score with the same p-value, so that a few pairs (df 4) are not combined by
// Stouffer's method as if their t were already a z.
#include <span>

namespace sd::statistics {

struct PairedTest {
  double statistic = 0.0;  // t of the differences x - y
  double df = 0.0;         // pairs - 1
  double p_value = 1.0;    // two-sided
  double z = 0.0;          // the normal score of the same one-sided p, with t's sign
};

/// Throws std::invalid_argument for fewer than 2 pairs, samples of different sizes or a
/// non-finite value. Identical differences give t 0 (all zero) or an infinite t.
PairedTest paired_t_test(std::span<const double> x, std::span<const double> y);

}  // namespace sd::statistics
