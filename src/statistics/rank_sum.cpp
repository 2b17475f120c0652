#include "statistics/rank_sum.hpp"

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "statistics/ranks.hpp"

namespace sd::statistics {

namespace {

bool any_nan(std::span<const double> x) {
  return std::any_of(x.begin(), x.end(), [](double v) { return std::isnan(v); });
}

// counts[u] = number of orderings of m x's and n y's in which exactly u (x, y) pairs have the
// x above the y, i.e. the null distribution of W times choose(m + n, n). The largest of the
// m + n values is either an x (beating all n y's) or a y, hence
//   c(u; m, n) = c(u - n; m - 1, n) + c(u; m, n - 1),
// which only adds non-negative counts: doubles stay exact up to 2^53 and relatively accurate
// beyond, where R's cwilcox uses doubles too.
std::vector<double> rank_sum_counts(int m, int n) {
  // by_m[j] holds c(.; j, nn) for the current nn, a vector of size j * nn + 1.
  std::vector<std::vector<double>> by_m(static_cast<std::size_t>(m) + 1, std::vector<double>{1.0});
  for (int nn = 1; nn <= n; ++nn) {
    for (int j = 1; j <= m; ++j) {
      auto& cur = by_m[static_cast<std::size_t>(j)];
      const auto& fewer_x = by_m[static_cast<std::size_t>(j) - 1];  // already at nn
      cur.resize(static_cast<std::size_t>(j) * static_cast<std::size_t>(nn) + 1, 0.0);
      const auto shift = static_cast<std::size_t>(nn);  // an x above all nn y's adds nn
      for (std::size_t u = shift; u < cur.size(); ++u) cur[u] += fewer_x[u - shift];
    }
  }
  return by_m[static_cast<std::size_t>(m)];
}

// R's pwilcox(q, m, n, lower.tail): sums the shorter tail of the symmetric distribution so
// that small upper-tail probabilities are not lost to 1 - (something close to 1).
double wilcox_cdf(double q, int m, int n, bool lower_tail) {
  if (m < 1 || n < 1) throw std::invalid_argument("pwilcox: sample sizes must be >= 1");
  const double mn = static_cast<double>(m) * static_cast<double>(n);
  q = std::floor(q + 1e-7);  // R's fuzz: W is an integer
  if (q < 0) return lower_tail ? 0.0 : 1.0;
  if (q >= mn) return lower_tail ? 1.0 : 0.0;
  const std::vector<double> counts = rank_sum_counts(m, n);
  double total = 0.0;
  for (double c : counts) total += c;
  double tail = 0.0;
  if (q <= mn / 2) {
    for (int u = 0; u <= static_cast<int>(q); ++u) tail += counts[static_cast<std::size_t>(u)] / total;
  } else {
    // P(W <= q) = 1 - P(W > q) = 1 - P(W < mn - q) by symmetry.
    const int upper = static_cast<int>(mn - q);
    for (int u = 0; u < upper; ++u) tail += counts[static_cast<std::size_t>(u)] / total;
    lower_tail = !lower_tail;
  }
  return lower_tail ? tail : 0.5 - tail + 0.5;
}

}  // namespace

double pwilcox(double q, int m, int n) { return wilcox_cdf(q, m, n, true); }

RankSumTest wilcoxon_rank_sum(std::span<const double> x, std::span<const double> y) {
  if (x.empty() || y.empty()) throw std::invalid_argument("wilcoxon_rank_sum: empty sample");
  if (any_nan(x) || any_nan(y)) throw std::invalid_argument("wilcoxon_rank_sum: NaN in a sample");
  std::vector<double> both(x.begin(), x.end());
  both.insert(both.end(), y.begin(), y.end());
  const std::vector<double> ranks = average_ranks(both);
  const double nx = static_cast<double>(x.size()), ny = static_cast<double>(y.size());
  RankSumTest out;
  for (std::size_t i = 0; i < x.size(); ++i) out.statistic += ranks[i];
  out.statistic -= nx * (nx + 1) / 2;

  const double ties = tie_term(both);
  out.exact = nx < 50 && ny < 50 && ties == 0;
  if (out.exact) {
    const int m = static_cast<int>(x.size()), n = static_cast<int>(y.size());
    const double p = out.statistic > nx * ny / 2 ? wilcox_cdf(out.statistic - 1, m, n, false)
                                                : wilcox_cdf(out.statistic, m, n, true);
    out.p_value = std::min(2 * p, 1.0);
    return out;
  }
  const double z = out.statistic - nx * ny / 2;
  const double sigma = std::sqrt((nx * ny / 12) * ((nx + ny + 1) - ties / ((nx + ny) * (nx + ny - 1))));
  if (!(sigma > 0)) {  // every value equal: R computes 0/0
    out.p_value = std::numeric_limits<double>::quiet_NaN();
    return out;
  }
  const double correction = z > 0 ? 0.5 : (z < 0 ? -0.5 : 0.0);
  const double zc = (z - correction) / sigma;
  const boost::math::normal normal;
  out.p_value = 2 * std::min(boost::math::cdf(normal, zc), boost::math::cdf(boost::math::complement(normal, zc)));
  return out;
}

}  // namespace sd::statistics
