#include "design/statistics.hpp"

#include <algorithm>
#include <boost/math/distributions/chi_squared.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <map>
#include <numeric>
#include <stdexcept>

namespace sd::design {

std::vector<double> average_ranks(std::span<const double> x) {
  const std::size_t n = x.size();
  std::vector<std::size_t> idx(n);
  std::iota(idx.begin(), idx.end(), 0);
  std::stable_sort(idx.begin(), idx.end(), [&](std::size_t a, std::size_t b) { return x[a] < x[b]; });
  std::vector<double> r(n);
  for (std::size_t i = 0; i < n;) {
    std::size_t j = i;
    while (j + 1 < n && x[idx[j + 1]] == x[idx[i]]) ++j;
    const double avg = (static_cast<double>(i + 1) + static_cast<double>(j + 1)) / 2.0;
    for (std::size_t k = i; k <= j; ++k) r[idx[k]] = avg;
    i = j + 1;
  }
  return r;
}

namespace {

// Within-row ranks of the whole matrix, and the tie term sum over rows/tie groups of t^3 - t.
CostMatrix row_ranks(const CostMatrix& y, double* tie_term) {
  CostMatrix r(y.rows, y.cols);
  double ties = 0.0;
  for (std::size_t i = 0; i < y.rows; ++i) {
    const auto ri = average_ranks(std::span<const double>(&y.data[i * y.cols], y.cols));
    std::map<double, double> groups;
    for (std::size_t j = 0; j < y.cols; ++j) {
      r.at(i, j) = ri[j];
      groups[ri[j]] += 1.0;
    }
    for (const auto& [rank, t] : groups) ties += t * t * t - t;
  }
  if (tie_term) *tie_term = ties;
  return r;
}

std::vector<double> column_sums(const CostMatrix& m) {
  std::vector<double> s(m.cols, 0.0);
  for (std::size_t i = 0; i < m.rows; ++i)
    for (std::size_t j = 0; j < m.cols; ++j) s[j] += m.at(i, j);
  return s;
}

// R order(): indices sorted by value, ties kept in their original order.
std::vector<std::size_t> order_of(const std::vector<double>& v) {
  std::vector<std::size_t> o(v.size());
  std::iota(o.begin(), o.end(), 0);
  std::stable_sort(o.begin(), o.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
  return o;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2.0;
}

// Standardised signed-rank statistic of x - d without continuity correction (R's W(d) used
// for the confidence interval and the estimate).
double standardised_signed_rank(const std::vector<double>& x, double d) {
  std::vector<double> xd;
  for (double v : x)
    if (v - d != 0.0) xd.push_back(v - d);
  const double nx = static_cast<double>(xd.size());
  std::vector<double> a(xd.size());
  for (std::size_t i = 0; i < xd.size(); ++i) a[i] = std::fabs(xd[i]);
  const auto r = average_ranks(a);
  double v = 0.0;
  std::map<double, double> groups;
  for (std::size_t i = 0; i < xd.size(); ++i) {
    if (xd[i] > 0) v += r[i];
    groups[r[i]] += 1.0;
  }
  double ties = 0.0;
  for (const auto& [rank, t] : groups) ties += t * t * t - t;
  const double sigma = std::sqrt(nx * (nx + 1) * (2 * nx + 1) / 24.0 - ties / 48.0);
  return (v - nx * (nx + 1) / 4.0) / sigma;
}

}  // namespace

std::vector<double> friedman_rank_sums(const CostMatrix& y) { return column_sums(row_ranks(y, nullptr)); }

FriedmanTest friedman_test(const CostMatrix& y) {
  if (y.cols < 2 || y.rows < 1) throw std::invalid_argument("friedman_test needs >= 2 columns and >= 1 row");
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

RaceTestOutcome friedman_conover(const CostMatrix& y, double confidence) {
  const FriedmanTest f = friedman_test(y);
  const auto& R = f.rank_sums;
  const auto o = order_of(R);
  RaceTestOutcome out;
  out.keep.assign(y.cols, true);
  out.best = o[0];
  out.p_value = f.p_value;
  const double alpha = 1.0 - confidence;
  if (std::isnan(f.p_value) || !(f.p_value < alpha)) return out;

  const CostMatrix r = row_ranks(y, nullptr);
  double A = 0.0, sumR2 = 0.0;
  for (double v : r.data) A += v * v;
  for (double v : R) sumR2 += v * v;
  const double n = static_cast<double>(y.rows), k = static_cast<double>(y.cols);
  const double df = (n - 1) * (k - 1);
  boost::math::students_t t_dist(df);
  out.critical_difference =
      boost::math::quantile(t_dist, 1 - alpha / 2) * std::sqrt(2 * (n * A - sumR2) / df);
  out.keep.assign(y.cols, false);
  out.keep[o[0]] = true;
  for (std::size_t j = 1; j < o.size(); ++j) {
    if (std::fabs(R[o[j]] - R[o[0]]) > out.critical_difference) break;
    out.keep[o[j]] = true;
  }
  out.dropped_any = true;
  return out;
}

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

WilcoxonTest wilcoxon_signed_rank(std::span<const double> x, std::span<const double> y) {
  if (x.size() != y.size()) throw std::invalid_argument("wilcoxon_signed_rank: lengths differ");
  std::vector<double> d;
  bool zeroes = false;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double v = x[i] - y[i];
    if (v == 0.0) zeroes = true;
    else d.push_back(v);
  }
  WilcoxonTest out;
  const std::size_t nn = d.size();
  if (nn == 0) throw std::invalid_argument("wilcoxon_signed_rank: all differences are zero");
  const double n = static_cast<double>(nn);
  std::vector<double> a(nn);
  for (std::size_t i = 0; i < nn; ++i) a[i] = std::fabs(d[i]);
  const auto r = average_ranks(a);
  std::map<double, double> groups;
  for (std::size_t i = 0; i < nn; ++i) {
    if (d[i] > 0) out.statistic += r[i];
    groups[r[i]] += 1.0;
  }
  const bool ties = groups.size() != nn;
  out.exact = n < 50 && !ties && !zeroes;
  if (out.exact) {
    const int ni = static_cast<int>(nn);
    const double p = out.statistic > n * (n + 1) / 4 ? 1.0 - psignrank(out.statistic - 1, ni)
                                                     : psignrank(out.statistic, ni);
    out.p_value = std::min(2 * p, 1.0);
    std::vector<double> walsh;
    walsh.reserve(nn * (nn + 1) / 2);
    for (std::size_t i = 0; i < nn; ++i)
      for (std::size_t j = i; j < nn; ++j) walsh.push_back((d[i] + d[j]) / 2);
    out.estimate = median(std::move(walsh));
    return out;
  }
  double tie_term = 0.0;
  for (const auto& [rank, t] : groups) tie_term += t * t * t - t;
  double z = out.statistic - n * (n + 1) / 4;
  const double sigma = std::sqrt(n * (n + 1) * (2 * n + 1) / 24 - tie_term / 48);
  const double correction = z > 0 ? 0.5 : (z < 0 ? -0.5 : 0.0);
  z = (z - correction) / sigma;
  boost::math::normal norm;
  out.p_value = 2 * std::min(boost::math::cdf(norm, z), boost::math::cdf(boost::math::complement(norm, z)));
  // Estimate: root of W(d) on [min, max]; W(min) > 0 > W(max) and W decreases in d.
  double lo = *std::min_element(d.begin(), d.end()), hi = *std::max_element(d.begin(), d.end());
  const double w_lo = standardised_signed_rank(d, lo), w_hi = standardised_signed_rank(d, hi);
  if (!std::isfinite(w_lo) || !std::isfinite(w_hi)) {
    out.estimate = (lo + hi) / 2;  // R: midrange when W cannot be computed
    return out;
  }
  for (int it = 0; it < 200 && hi - lo > 1e-12 * std::max(1.0, std::fabs(lo) + std::fabs(hi)); ++it) {
    const double mid = (lo + hi) / 2;
    if (standardised_signed_rank(d, mid) > 0) lo = mid;
    else hi = mid;
  }
  out.estimate = (lo + hi) / 2;
  return out;
}

RaceTestOutcome race_test(const CostMatrix& y, double confidence) {
  if (y.cols != 2) return friedman_conover(y, confidence);
  RaceTestOutcome out;
  out.keep = {true, true};
  out.dropped_any = true;
  out.p_value = 0.0;
  bool first_dominates = true, second_dominates = true;
  std::vector<double> v1(y.rows), v2(y.rows);
  for (std::size_t i = 0; i < y.rows; ++i) {
    v1[i] = y.at(i, 0);
    v2[i] = y.at(i, 1);
    if (!(v1[i] <= v2[i])) first_dominates = false;
    if (!(v2[i] <= v1[i])) second_dominates = false;
  }
  std::size_t worse;
  if (first_dominates) {
    worse = 1;
  } else if (second_dominates) {
    worse = 0;
  } else {
    const WilcoxonTest w = wilcoxon_signed_rank(v1, v2);
    out.p_value = w.p_value;
    if (w.p_value >= 1 - confidence) out.dropped_any = false;
    worse = w.estimate <= 0 ? 1 : 0;
  }
  out.best = 1 - worse;
  if (out.dropped_any) out.keep[worse] = false;
  return out;
}

}  // namespace sd::design
