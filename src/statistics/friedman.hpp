#pragma once
// The Friedman rank-sum test over blocks (rows) and treatments (columns), and Conover's
// post-hoc critical difference on its rank sums: the race's elimination test (irace 3.5 R/race.R
// aux2.friedman) and the report's comparison of conditions across missions both stand on it.
// Ranks are taken within each row, lowest first, ties averaged (R's rank()).
#include <cstddef>
#include <vector>

namespace sd::statistics {

/// Row-major matrix of costs: rows are blocks (instances, missions), columns are treatments
/// (configurations, conditions); the lowest cost of a row gets rank 1.
struct CostMatrix {
  std::size_t rows = 0, cols = 0;
  std::vector<double> data;
  CostMatrix() = default;
  CostMatrix(std::size_t r, std::size_t c) : rows(r), cols(c), data(r * c, 0.0) {}
  double& at(std::size_t r, std::size_t c) { return data[r * cols + c]; }
  double at(std::size_t r, std::size_t c) const { return data[r * cols + c]; }
};

/// Per-column sums of the within-row ranks (the Friedman rank sums R_j); all 0 with no rows.
std::vector<double> friedman_rank_sums(const CostMatrix& y);

struct FriedmanTest {
  double statistic = 0.0;  // NaN when every row is a complete tie
  double p_value = 1.0;    // P(chi^2_{k-1} > statistic); NaN with the statistic
  std::vector<double> rank_sums;
};
/// Friedman rank-sum test with the tie correction (R friedman.test). Throws
/// std::invalid_argument unless y has >= 1 row and >= 2 columns.
FriedmanTest friedman_test(const CostMatrix& y);

/// Conover's critical difference on the rank sums (irace aux2.friedman, PMCMR): two columns
/// differ at level alpha when their rank sums differ by more than
///   qt(1 - alpha/2, (n-1)(k-1)) * sqrt(2 (n A - sum_j R_j^2) / ((n-1)(k-1))),
/// n rows, k columns, A the sum of the squared within-row ranks, R_j the rank sums.
/// 0 when every row ranks the columns alike (n A == sum R_j^2 exactly: ranks are multiples of
/// 1/2); NaN with a single row (no degrees of freedom to estimate the spread from).
/// Throws std::invalid_argument unless y has >= 1 row and >= 2 columns.
double conover_critical_difference(const CostMatrix& y, double alpha);

}  // namespace sd::statistics
