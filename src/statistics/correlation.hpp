#pragma once
// Rank correlation: do two simulators order the same controllers alike?
#include <span>

namespace sd::statistics {

/// R's cor(x, y, method = "spearman"): Pearson's correlation of the average ranks (ties
/// averaged). NaN when either sample is constant (zero variance of its ranks). Throws
/// std::invalid_argument unless x and y have the same size >= 2.
double spearman_rho(std::span<const double> x, std::span<const double> y);

}  // namespace sd::statistics
