#pragma once
// The t confidence interval of a mean, as R's t.test(x)$conf.int: for a drop across the
// reality gap (app/assess_job), where the per-seed differences are the sample.
#include <span>

namespace sd::statistics {

struct MeanInterval {
  double mean = 0.0, low = 0.0, high = 0.0;
};

/// Two-sided interval at `level` (0.95: 95 %). One value, or values all equal, give the mean
/// as both ends. Throws std::invalid_argument for no value or a non-finite one.
MeanInterval t_interval(std::span<const double> x, double level = 0.95);

}  // namespace sd::statistics
