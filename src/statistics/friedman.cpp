#include "statistics/friedman.hpp"

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>

#include "statistics/ranks.hpp"

namespace sd::statistics {

namespace {

void check_shape(const CostMatrix& y, const char* what) {
  if (y.cols < 2 || y.rows < 1) throw std::invalid_argument(std::string(what) + " needs >= 2 columns and >= 1 row");
}

// Within-row ranks of the whole matrix; adds each row's tie term to *ties when asked.
CostMatrix row_ranks(const CostMatrix& y, double* ties) {
  CostMatrix r(y.rows, y.cols);
  for (std::size_t i = 0; i < y.rows; ++i) {
    const std::span<const double> row(&y.data[i * y.cols], y.cols);
    const auto ri = average_ranks(row);
    std::copy(ri.begin(), ri.end(), r.data.begin() + static_cast<std::ptrdiff_t>(i * y.cols));
    if (ties) *ties += tie_term(row);
  }
  return r;
}

std::vector<double> column_sums(const CostMatrix& m) {
  std::vector<double> s(m.cols, 0.0);
  for (std::size_t i = 0; i < m.rows; ++i)
    for (std::size_t j = 0; j < m.cols; ++j) s[j] += m.at(i, j);
  return s;
}

}  // namespace

std::vector<double> friedman_rank_sums(const CostMatrix& y) { return column_sums(row_ranks(y, nullptr)); }

FriedmanTest friedman_test(const CostMatrix& y) {
  check_shape(y, "friedman_test");
  double ties = 0.0;
  const CostMatrix r = row_ranks(y, &ties);
  FriedmanTest out;
  out.rank_sums = column_sums(r);
  const double n = static_cast<double>(y.rows), k = static_cast<double>(y.cols);
  double ss = 0.0;
  for (double rj : out.rank_sums) ss += (rj - n * (k + 1) / 2) * (rj - n * (k + 1) / 2);
  out.statistic = 12.0 * ss / (n * k * (k + 1) - ties / (k - 1));
  if (std::isfinite(out.statistic)) {
    boost::math::chi_squared chi(k - 1);
    out.p_value = boost::math::cdf(boost::math::complement(chi, std::max(0.0, out.statistic)));
  } else {
    out.p_value = std::numeric_limits<double>::quiet_NaN();
  }
  return out;
}

double conover_critical_difference(const CostMatrix& y, double alpha) {
  check_shape(y, "conover_critical_difference");
  const double n = static_cast<double>(y.rows), k = static_cast<double>(y.cols);
  const double df = (n - 1) * (k - 1);
  if (!(df > 0)) return std::numeric_limits<double>::quiet_NaN();
  const CostMatrix r = row_ranks(y, nullptr);
  double a = 0.0, sum_r2 = 0.0;
  for (double v : r.data) a += v * v;
  for (double v : column_sums(r)) sum_r2 += v * v;
  const boost::math::students_t t(df);
  return boost::math::quantile(t, 1 - alpha / 2) * std::sqrt(2 * (n * a - sum_r2) / df);
}

}  // namespace sd::statistics
