#include "statistics/correlation.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "statistics/ranks.hpp"

namespace sd::statistics {

double spearman_rho(std::span<const double> x, std::span<const double> y) {
  if (x.size() != y.size() || x.size() < 2) throw std::invalid_argument("Spearman's rho needs two samples of the same size >= 2");
  const std::vector<double> rx = average_ranks(x), ry = average_ranks(y);
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

}  // namespace sd::statistics
