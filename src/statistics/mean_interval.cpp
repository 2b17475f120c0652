#include "statistics/mean_interval.hpp"

#include <boost/math/distributions/students_t.hpp>

#include <cmath>
#include <stdexcept>

#include "statistics/descriptive.hpp"

namespace sd::statistics {

MeanInterval t_interval(std::span<const double> x, double level) {
  if (x.empty()) throw std::invalid_argument("t_interval: no value");
  for (const double v : x)
    if (!std::isfinite(v)) throw std::invalid_argument("t_interval: a value is not finite");
  const double m = mean(x);
  if (x.size() < 2) return {m, m, m};
  const double se = sample_standard_deviation(x) / std::sqrt(static_cast<double>(x.size()));
  if (se == 0.0) return {m, m, m};
  const boost::math::students_t t(static_cast<double>(x.size() - 1));
  const double q = boost::math::quantile(boost::math::complement(t, (1.0 - level) / 2.0));
  return {m, m - q * se, m + q * se};
}

}  // namespace sd::statistics
