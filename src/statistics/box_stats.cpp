#include "statistics/box_stats.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace sd::statistics {

namespace {

// fivenum()'s order statistic at the 1-based, possibly half-integer position d.
double order_stat(const std::vector<double>& sorted, double d) {
  const auto lo = static_cast<std::size_t>(std::floor(d)) - 1, hi = static_cast<std::size_t>(std::ceil(d)) - 1;
  return 0.5 * (sorted[lo] + sorted[hi]);
}

}  // namespace

BoxStats box_stats(std::span<const double> x) {
  if (x.empty()) throw std::invalid_argument("box_stats: empty input");
  if (!std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); }))
    throw std::invalid_argument("box_stats: non-finite value");
  std::vector<double> sorted(x.begin(), x.end());
  std::sort(sorted.begin(), sorted.end());
  const double n = static_cast<double>(sorted.size());

  BoxStats b;
  b.n = sorted.size();
  // fivenum(): the hinges are medians of the lower and upper halves (both include the median
  // when n is odd), not quantile()'s interpolated quartiles.
  const double n4 = std::floor((n + 3) / 2) / 2;
  b.min = sorted.front();
  b.q1 = order_stat(sorted, n4);
  b.median = order_stat(sorted, (n + 1) / 2);
  b.q3 = order_stat(sorted, n + 1 - n4);
  b.max = sorted.back();

  const double iqr = b.q3 - b.q1;
  const double low_fence = b.q1 - 1.5 * iqr, high_fence = b.q3 + 1.5 * iqr;
  // Sorted, the outliers are a prefix and a suffix; the whiskers end at what lies between.
  const auto first_in = std::find_if(sorted.begin(), sorted.end(), [&](double v) { return !(v < low_fence); });
  const auto past_in = std::find_if(first_in, sorted.end(), [&](double v) { return v > high_fence; });
  b.whisker_low = *first_in;  // never end(): the median lies between the fences
  b.whisker_high = *(past_in - 1);
  b.outliers.assign(sorted.begin(), first_in);
  b.outliers.insert(b.outliers.end(), past_in, sorted.end());

  // R: stats[3] + c(-1.58, 1.58) * iqr / sqrt(n), McGill et al.'s ~95 % notch for medians.
  b.notch_low = b.median + (-1.58 * iqr) / std::sqrt(n);
  b.notch_high = b.median + (1.58 * iqr) / std::sqrt(n);
  return b;
}

}  // namespace sd::statistics
