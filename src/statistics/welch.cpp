#include "statistics/welch.hpp"

#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <utility>

#include "statistics/descriptive.hpp"

namespace sd::statistics {

namespace {

// The sample's mean and its squared standard error var(x) / n.
std::pair<double, double> mean_and_squared_error(std::span<const double> v) {
  if (v.size() < 2) throw std::invalid_argument("Welch's t-test needs at least 2 values per sample");
  for (const double value : v)
    if (!std::isfinite(value)) throw std::invalid_argument("Welch's t-test needs finite values");
  return {mean(v), sample_variance(v) / static_cast<double>(v.size())};
}

}  // namespace

WelchTest welch_t_test(std::span<const double> x, std::span<const double> y) {
  const auto [mx, vx] = mean_and_squared_error(x);
  const auto [my, vy] = mean_and_squared_error(y);
  WelchTest out;
  const double se2 = vx + vy;
  if (se2 == 0.0) {
    out.statistic = mx == my ? 0.0 : std::copysign(std::numeric_limits<double>::infinity(), mx - my);
    out.df = static_cast<double>(x.size() + y.size() - 2);
    out.p_value = mx == my ? 1.0 : 0.0;
    return out;
  }
  out.statistic = (mx - my) / std::sqrt(se2);
  out.df = se2 * se2 / (vx * vx / static_cast<double>(x.size() - 1) + vy * vy / static_cast<double>(y.size() - 1));
  const boost::math::students_t t(out.df);
  out.p_value = 2.0 * boost::math::cdf(boost::math::complement(t, std::abs(out.statistic)));
  return out;
}

}  // namespace sd::statistics
