#include "statistics/descriptive.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace sd::statistics {

double mean(std::span<const double> x) {
  if (x.empty()) throw std::invalid_argument("mean: empty input");
  return std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
}

double sample_variance(std::span<const double> x) {
  if (x.size() < 2) throw std::invalid_argument("sample variance: needs at least 2 values");
  const double m = mean(x);
  double sum_squares = 0.0;
  for (const double value : x) sum_squares += (value - m) * (value - m);
  return sum_squares / static_cast<double>(x.size() - 1);
}

double sample_standard_deviation(std::span<const double> x) { return std::sqrt(sample_variance(x)); }

double median(std::span<const double> x) {
  if (x.empty()) throw std::invalid_argument("median: empty input");
  if (std::any_of(x.begin(), x.end(), [](double v) { return std::isnan(v); }))
    return std::numeric_limits<double>::quiet_NaN();
  std::vector<double> v(x.begin(), x.end());
  const std::size_t half = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(half), v.end());
  if (v.size() % 2) return v[half];
  const double upper = v[half];
  const double lower = *std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(half));
  return (lower + upper) / 2;
}

}  // namespace sd::statistics
