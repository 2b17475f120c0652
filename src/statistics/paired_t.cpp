#include "statistics/paired_t.hpp"

#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "statistics/descriptive.hpp"

namespace sd::statistics {

PairedTest paired_t_test(std::span<const double> x, std::span<const double> y) {
  if (x.size() != y.size()) throw std::invalid_argument("the paired t-test needs samples of the same size");
  if (x.size() < 2) throw std::invalid_argument("the paired t-test needs at least 2 pairs");
  std::vector<double> d(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i]) || !std::isfinite(y[i])) throw std::invalid_argument("the paired t-test needs finite values");
    d[i] = x[i] - y[i];
  }
  PairedTest out;
  out.df = static_cast<double>(d.size() - 1);
  const double m = mean(d), se = sample_standard_deviation(d) / std::sqrt(static_cast<double>(d.size()));
  if (se == 0.0) {
    out.statistic = m == 0.0 ? 0.0 : std::copysign(std::numeric_limits<double>::infinity(), m);
    out.p_value = m == 0.0 ? 1.0 : 0.0;
    out.z = out.statistic;
    return out;
  }
  out.statistic = m / se;
  const boost::math::students_t t(out.df);
  const double upper = boost::math::cdf(boost::math::complement(t, std::abs(out.statistic)));  // one-sided
  out.p_value = 2.0 * upper;
  const boost::math::normal normal;
  out.z = upper <= 0.0 ? std::copysign(std::numeric_limits<double>::infinity(), out.statistic)
                       : std::copysign(boost::math::quantile(boost::math::complement(normal, upper)), out.statistic);
  return out;
}

}  // namespace sd::statistics
