#include "experiments/statistics.hpp"

#include <algorithm>
#include <boost/math/distributions/binomial.hpp>
#include <boost/math/distributions/normal.hpp>
#include <boost/math/distributions/students_t.hpp>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "design/statistics.hpp"

namespace sd::experiments {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool any_nan(std::span<const double> x) {
  return std::any_of(x.begin(), x.end(), [](double v) { return std::isnan(v); });
}

bool all_finite(std::span<const double> x) {
  return std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); });
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

// Sum over groups of equal values of t^3 - t (t = group size): the tie correction term.
double tie_term(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  double term = 0.0;
  for (std::size_t i = 0; i < v.size();) {
    std::size_t j = i;
    while (j < v.size() && v[j] == v[i]) ++j;
    const double t = static_cast<double>(j - i);
    term += t * t * t - t;
    i = j;
  }
  return term;
}

// fivenum()'s order statistic at the 1-based, possibly half-integer position d.
double order_stat(const std::vector<double>& sorted, double d) {
  const auto lo = static_cast<std::size_t>(std::floor(d)) - 1, hi = static_cast<std::size_t>(std::ceil(d)) - 1;
  return 0.5 * (sorted[lo] + sorted[hi]);
}

void check_matrix(const std::vector<std::vector<double>>& values, const std::vector<bool>& higher_is_better,
                  double confidence) {
  if (values.empty()) throw std::invalid_argument("expected_ranks: no blocks");
  if (values.size() != higher_is_better.size())
    throw std::invalid_argument("expected_ranks: one higher_is_better entry per block is needed");
  const std::size_t k = values.front().size();
  if (k < 2) throw std::invalid_argument("expected_ranks: at least two conditions are needed");
  for (const auto& row : values) {
    if (row.size() != k) throw std::invalid_argument("expected_ranks: blocks have different numbers of conditions");
    if (!all_finite(row)) throw std::invalid_argument("expected_ranks: non-finite value");
  }
  if (!(confidence > 0 && confidence < 1)) throw std::invalid_argument("expected_ranks: confidence must be in (0, 1)");
}

// Conover's post-hoc test (as irace's aux2.friedman / PMCMR) declares two conditions different
// when their rank sums differ by more than
//   qt(1 - alpha/2, (b-1)(k-1)) * sqrt(2 (b A - sum_j R_j^2) / ((b-1)(k-1))),
// A being the sum of the squared within-block ranks and R_j the rank sums. Dividing by the b
// blocks puts it on the scale of the mean ranks the report shows. b A == sum R_j^2 exactly when
// every block ranks the conditions alike: if the test rejected, that is perfect agreement and
// the CD is 0 (any difference in mean rank is significant); all-tied blocks never get here, the
// Friedman statistic being NaN.
std::optional<double> conover_mean_rank_cd(const design::CostMatrix& costs, const std::vector<double>& rank_sums,
                                           double alpha) {
  const double b = static_cast<double>(costs.rows), k = static_cast<double>(costs.cols);
  const double df = (b - 1) * (k - 1);
  if (!(df > 0)) return std::nullopt;  // one block: nothing to estimate the spread from
  double a = 0.0;
  for (std::size_t i = 0; i < costs.rows; ++i)
    for (double r : design::average_ranks(std::span<const double>(&costs.data[i * costs.cols], costs.cols))) a += r * r;
  double sum_r2 = 0.0;
  for (double r : rank_sums) sum_r2 += r * r;
  // Ranks are multiples of 1/2, so these sums are exact and the spread is never negative.
  const double spread = b * a - sum_r2;
  const double t = boost::math::quantile(boost::math::students_t(df), 1 - alpha / 2);
  return t * std::sqrt(2 * spread / df) / b;
}

}  // namespace

double pwilcox(double q, int m, int n) { return wilcox_cdf(q, m, n, true); }

RankSumTest wilcoxon_rank_sum(std::span<const double> x, std::span<const double> y) {
  if (x.empty() || y.empty()) throw std::invalid_argument("wilcoxon_rank_sum: empty sample");
  if (any_nan(x) || any_nan(y)) throw std::invalid_argument("wilcoxon_rank_sum: NaN in a sample");
  std::vector<double> both(x.begin(), x.end());
  both.insert(both.end(), y.begin(), y.end());
  const std::vector<double> ranks = design::average_ranks(both);
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
    out.p_value = kNaN;
    return out;
  }
  const double correction = z > 0 ? 0.5 : (z < 0 ? -0.5 : 0.0);
  const double zc = (z - correction) / sigma;
  const boost::math::normal normal;
  out.p_value = 2 * std::min(boost::math::cdf(normal, zc), boost::math::cdf(boost::math::complement(normal, zc)));
  return out;
}

double median(std::span<const double> x) {
  if (x.empty()) throw std::invalid_argument("median: empty input");
  std::vector<double> v(x.begin(), x.end());
  const std::size_t half = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(half), v.end());
  if (v.size() % 2) return v[half];
  const double upper = v[half];
  const double lower = *std::max_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(half));
  return (lower + upper) / 2;
}

BoxStats box_stats(std::span<const double> x) {
  if (x.empty()) throw std::invalid_argument("box_stats: empty input");
  if (!all_finite(x)) throw std::invalid_argument("box_stats: non-finite value");
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

ExpectedRanks expected_ranks(const std::vector<std::vector<double>>& values, const std::vector<bool>& higher_is_better,
                             double confidence) {
  check_matrix(values, higher_is_better, confidence);
  const std::size_t blocks = values.size(), k = values.front().size();
  // Friedman ranks lowest first, so maximised missions are negated to make rank 1 the best.
  design::CostMatrix costs(blocks, k);
  for (std::size_t i = 0; i < blocks; ++i)
    for (std::size_t j = 0; j < k; ++j) costs.at(i, j) = higher_is_better[i] ? -values[i][j] : values[i][j];

  const design::FriedmanTest f = design::friedman_test(costs);
  ExpectedRanks out;
  out.statistic = f.statistic;
  out.p_value = f.p_value;
  out.df = static_cast<int>(k) - 1;
  out.mean_ranks.reserve(k);
  for (double r : f.rank_sums) out.mean_ranks.push_back(r / static_cast<double>(blocks));
  const double alpha = 1 - confidence;
  if (f.p_value < alpha) out.critical_difference = conover_mean_rank_cd(costs, f.rank_sums, alpha);
  return out;
}

double mean(std::span<const double> x) { return std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size()); }

double sample_standard_deviation(std::span<const double> x) {
  const double m = mean(x);
  double sum_squares = 0.0;
  for (const double value : x) sum_squares += (value - m) * (value - m);
  return std::sqrt(sum_squares / static_cast<double>(x.size() - 1));
}

WelchTest welch_t_test(std::span<const double> x, std::span<const double> y) {
  const auto moments = [](std::span<const double> v) {
    if (v.size() < 2) throw std::invalid_argument("Welch's t-test needs at least 2 values per sample");
    double mean = 0.0;
    for (const double value : v) {
      if (!std::isfinite(value)) throw std::invalid_argument("Welch's t-test needs finite values");
      mean += value;
    }
    mean /= static_cast<double>(v.size());
    double sum_squares = 0.0;
    for (const double value : v) sum_squares += (value - mean) * (value - mean);
    return std::pair{mean, sum_squares / static_cast<double>(v.size() - 1) / static_cast<double>(v.size())};
  };
  const auto [mx, vx] = moments(x);  // vx, vy: squared standard errors
  const auto [my, vy] = moments(y);
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

double sign_test_p_value(int successes, int trials) {
  if (trials < 0 || successes < 0 || successes > trials) throw std::invalid_argument("sign test: 0 <= successes <= trials");
  if (trials == 0) return 1.0;
  // binom.test's two-sided p for p = 0.5: twice the smaller tail, capped at 1.
  const boost::math::binomial b(trials, 0.5);
  const int k = std::min(successes, trials - successes);
  return std::min(1.0, 2.0 * boost::math::cdf(b, k));
}

double spearman_rho(std::span<const double> x, std::span<const double> y) {
  if (x.size() != y.size() || x.size() < 2) throw std::invalid_argument("Spearman's rho needs two samples of the same size >= 2");
  const std::vector<double> rx = sd::design::average_ranks(x), ry = sd::design::average_ranks(y);
  const double n = static_cast<double>(x.size()), mean_rank = (n + 1.0) / 2.0;
  double sxy = 0.0, sxx = 0.0, syy = 0.0;
  for (std::size_t i = 0; i < rx.size(); ++i) {
    sxy += (rx[i] - mean_rank) * (ry[i] - mean_rank);
    sxx += (rx[i] - mean_rank) * (rx[i] - mean_rank);
    syy += (ry[i] - mean_rank) * (ry[i] - mean_rank);
  }
  if (sxx == 0.0 || syy == 0.0) return std::numeric_limits<double>::quiet_NaN();
  return sxy / std::sqrt(sxx * syy);
}

}  // namespace sd::experiments
