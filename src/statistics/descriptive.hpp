#pragma once
// Mean, variance, standard deviation and median as R computes them. Empty input is a caller's
// mistake here, not a value: each throws std::invalid_argument rather than returning NaN (R) or
// 0, because a NaN would travel silently into a report (JSON null) or make every comparison
// false, and a 0 is a score nobody obtained.
#include <span>

namespace sd::statistics {

/// R's mean(x): the sum in input order divided by the count. Throws on empty input; a NaN in x
/// gives NaN.
double mean(std::span<const double> x);

/// R's var(x): sum of squared deviations from the mean over n - 1. Throws unless x holds at
/// least 2 values; 0 when every value is the same.
double sample_variance(std::span<const double> x);

/// R's sd(x): the square root of sample_variance (same edge cases).
double sample_standard_deviation(std::span<const double> x);

/// R's median(x): the middle value, or the mean of the two middle ones. Throws on empty input;
/// NaN when x holds a NaN (R's NA).
double median(std::span<const double> x);

}  // namespace sd::statistics
