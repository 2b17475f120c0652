#pragma once
// Welch's two-sample t-test, as R's t.test(x, y): whether two simulators' mean scores agree.
#include <span>

namespace sd::statistics {

struct WelchTest {
  double statistic = 0.0;  // t
  double df = 0.0;         // Welch-Satterthwaite degrees of freedom
  double p_value = 1.0;    // two-sided
};
/// R's t.test(x, y) (Welch, two-sided). When both samples are constant the test is undefined
/// in R; here p is 1 if the constants are equal and 0 otherwise (t 0 or +-infinity, df
/// nx + ny - 2), so that two simulators that agree exactly pass and two that disagree exactly
/// fail. One constant sample is fine (its variance is 0).
/// Throws std::invalid_argument unless both samples have at least 2 values, all finite.
WelchTest welch_t_test(std::span<const double> x, std::span<const double> y);

}  // namespace sd::statistics
