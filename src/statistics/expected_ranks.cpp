#include "statistics/expected_ranks.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "statistics/friedman.hpp"

namespace sd::statistics {

namespace {

void check_matrix(const std::vector<std::vector<double>>& values, const std::vector<bool>& higher_is_better,
                  double confidence) {
  if (values.empty()) throw std::invalid_argument("expected_ranks: no blocks");
  if (values.size() != higher_is_better.size())
    throw std::invalid_argument("expected_ranks: one higher_is_better entry per block is needed");
  const std::size_t k = values.front().size();
  if (k < 2) throw std::invalid_argument("expected_ranks: at least two conditions are needed");
  for (const auto& row : values) {
    if (row.size() != k) throw std::invalid_argument("expected_ranks: blocks have different numbers of conditions");
    if (!std::all_of(row.begin(), row.end(), [](double v) { return std::isfinite(v); }))
      throw std::invalid_argument("expected_ranks: non-finite value");
  }
  if (!(confidence > 0 && confidence < 1)) throw std::invalid_argument("expected_ranks: confidence must be in (0, 1)");
}

}  // namespace

ExpectedRanks expected_ranks(const std::vector<std::vector<double>>& values, const std::vector<bool>& higher_is_better,
                             double confidence) {
  check_matrix(values, higher_is_better, confidence);
  const std::size_t blocks = values.size(), k = values.front().size();
  // Friedman ranks lowest first, so maximised missions are negated to make rank 1 the best.
  CostMatrix costs(blocks, k);
  for (std::size_t i = 0; i < blocks; ++i)
    for (std::size_t j = 0; j < k; ++j) costs.at(i, j) = higher_is_better[i] ? -values[i][j] : values[i][j];

  const FriedmanTest f = friedman_test(costs);
  ExpectedRanks out;
  out.statistic = f.statistic;
  out.p_value = f.p_value;
  out.df = static_cast<int>(k) - 1;
  out.mean_ranks.reserve(k);
  for (double r : f.rank_sums) out.mean_ranks.push_back(r / static_cast<double>(blocks));
  const double alpha = 1 - confidence;
  if (f.p_value < alpha) {
    const double cd = conover_critical_difference(costs, alpha);
    if (!std::isnan(cd)) out.critical_difference = cd / static_cast<double>(blocks);
  }
  return out;
}

}  // namespace sd::statistics
