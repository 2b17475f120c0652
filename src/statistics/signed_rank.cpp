#include "statistics/signed_rank.hpp"

#include <algorithm>
#include <boost/math/distributions/normal.hpp>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "statistics/descriptive.hpp"
#include "statistics/ranks.hpp"

namespace sd::statistics {

namespace {

std::vector<double> absolute(const std::vector<double>& x) {
  std::vector<double> a(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) a[i] = std::fabs(x[i]);
  return a;
}

// The signed-rank statistic's standard deviation under the null, ties corrected.
double null_sigma(double n, double ties) { return std::sqrt(n * (n + 1) * (2 * n + 1) / 24 - ties / 48); }

// Standardised signed-rank statistic of x - d without continuity correction (R's W(d) used
// for the confidence interval and the estimate).
double standardised_signed_rank(const std::vector<double>& x, double d) {
  std::vector<double> xd;
  for (double v : x)
    if (v - d != 0.0) xd.push_back(v - d);
  const double nx = static_cast<double>(xd.size());
  const std::vector<double> a = absolute(xd);
  const auto r = average_ranks(a);
  double v = 0.0;
  for (std::size_t i = 0; i < xd.size(); ++i)
    if (xd[i] > 0) v += r[i];
  return (v - nx * (nx + 1) / 4.0) / null_sigma(nx, tie_term(a));
}

// Hodges-Lehmann estimate: the median of the Walsh averages (d_i + d_j) / 2, i <= j.
double walsh_median(const std::vector<double>& d) {
  std::vector<double> walsh;
  walsh.reserve(d.size() * (d.size() + 1) / 2);
  for (std::size_t i = 0; i < d.size(); ++i)
    for (std::size_t j = i; j < d.size(); ++j) walsh.push_back((d[i] + d[j]) / 2);
  return median(walsh);
}

// Root of W(d) on [min, max]; W(min) > 0 > W(max) and W decreases in d.
double root_of_standardised_statistic(const std::vector<double>& d) {
  double lo = *std::min_element(d.begin(), d.end()), hi = *std::max_element(d.begin(), d.end());
  const double w_lo = standardised_signed_rank(d, lo), w_hi = standardised_signed_rank(d, hi);
  if (!std::isfinite(w_lo) || !std::isfinite(w_hi)) return (lo + hi) / 2;  // R: midrange when W cannot be computed
  for (int it = 0; it < 200 && hi - lo > 1e-12 * std::max(1.0, std::fabs(lo) + std::fabs(hi)); ++it) {
    const double mid = (lo + hi) / 2;
    if (standardised_signed_rank(d, mid) > 0) lo = mid;
    else hi = mid;
  }
  return (lo + hi) / 2;
}

}  // namespace

double psignrank(double q, int n) {
  if (n < 0) throw std::invalid_argument("psignrank: n < 0");
  const int max_sum = n * (n + 1) / 2;
  const double qq = std::floor(q + 1e-7);
  if (qq < 0) return 0.0;
  if (qq >= max_sum) return 1.0;
  // counts[s] = number of subsets of {1..n} whose sum is s
  std::vector<double> counts(static_cast<std::size_t>(max_sum) + 1, 0.0);
  counts[0] = 1.0;
  for (int k = 1; k <= n; ++k)
    for (int s = max_sum; s >= k; --s) counts[s] += counts[s - k];
  double below = 0.0;
  for (int s = 0; s <= static_cast<int>(qq); ++s) below += counts[s];
  return below / std::ldexp(1.0, n);
}

SignedRankTest wilcoxon_signed_rank(std::span<const double> x, std::span<const double> y) {
  if (x.size() != y.size()) throw std::invalid_argument("wilcoxon_signed_rank: lengths differ");
  std::vector<double> d;
  bool zeroes = false;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double v = x[i] - y[i];
    if (v == 0.0) zeroes = true;
    else d.push_back(v);
  }
  SignedRankTest out;
  const std::size_t nn = d.size();
  if (nn == 0) throw std::invalid_argument("wilcoxon_signed_rank: all differences are zero");
  const double n = static_cast<double>(nn);
  const std::vector<double> a = absolute(d);
  const auto r = average_ranks(a);
  for (std::size_t i = 0; i < nn; ++i)
    if (d[i] > 0) out.statistic += r[i];
  const double ties = tie_term(a);
  out.exact = n < 50 && ties == 0 && !zeroes;
  if (out.exact) {
    const int ni = static_cast<int>(nn);
    const double p = out.statistic > n * (n + 1) / 4 ? 1.0 - psignrank(out.statistic - 1, ni)
                                                     : psignrank(out.statistic, ni);
    out.p_value = std::min(2 * p, 1.0);
    out.estimate = walsh_median(d);
    return out;
  }
  double z = out.statistic - n * (n + 1) / 4;
  const double correction = z > 0 ? 0.5 : (z < 0 ? -0.5 : 0.0);
  z = (z - correction) / null_sigma(n, ties);
  boost::math::normal norm;
  out.p_value = 2 * std::min(boost::math::cdf(norm, z), boost::math::cdf(boost::math::complement(norm, z)));
  out.estimate = root_of_standardised_statistic(d);
  return out;
}

}  // namespace sd::statistics
