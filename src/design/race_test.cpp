#include "design/race_test.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "statistics/signed_rank.hpp"

namespace sd::design {

namespace {

// R order(): indices sorted by value, ties kept in their original order.
std::vector<std::size_t> order_of(const std::vector<double>& v) {
  std::vector<std::size_t> o(v.size());
  std::iota(o.begin(), o.end(), 0);
  std::stable_sort(o.begin(), o.end(), [&](std::size_t a, std::size_t b) { return v[a] < v[b]; });
  return o;
}

}  // namespace

RaceTestOutcome friedman_conover(const CostMatrix& y, double confidence) {
  const statistics::FriedmanTest f = statistics::friedman_test(y);
  const auto& R = f.rank_sums;
  const auto o = order_of(R);
  RaceTestOutcome out;
  out.keep.assign(y.cols, true);
  out.best = o[0];
  out.p_value = f.p_value;
  const double alpha = 1.0 - confidence;
  if (std::isnan(f.p_value) || !(f.p_value < alpha)) return out;

  out.critical_difference = statistics::conover_critical_difference(y, alpha);
  out.keep.assign(y.cols, false);
  out.keep[o[0]] = true;
  for (std::size_t j = 1; j < o.size(); ++j) {
    if (std::fabs(R[o[j]] - R[o[0]]) > out.critical_difference) break;
    out.keep[o[j]] = true;
  }
  out.dropped_any = true;
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
    const statistics::SignedRankTest w = statistics::wilcoxon_signed_rank(v1, v2);
    out.p_value = w.p_value;
    if (w.p_value >= 1 - confidence) out.dropped_any = false;
    worse = w.estimate <= 0 ? 1 : 0;
  }
  out.best = 1 - worse;
  if (out.dropped_any) out.keep[worse] = false;
  return out;
}

}  // namespace sd::design
