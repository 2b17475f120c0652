#pragma once
// The statistical tests of an F-race step (irace 3.5 R/race.R: aux2.friedman, aux_friedman).
// Distributions come from Boost.Math; the rank arithmetic follows R (rank() with average ties).
#include <cstddef>
#include <span>
#include <vector>

namespace sd::design {

/// Row-major matrix of costs: rows are instances (blocks), columns are configurations.
struct CostMatrix {
  std::size_t rows = 0, cols = 0;
  std::vector<double> data;
  CostMatrix() = default;
  CostMatrix(std::size_t r, std::size_t c) : rows(r), cols(c), data(r * c, 0.0) {}
  double& at(std::size_t r, std::size_t c) { return data[r * cols + c]; }
  double at(std::size_t r, std::size_t c) const { return data[r * cols + c]; }
};

/// R's rank(x): 1-based ranks, ties get the average of the ranks they span.
std::vector<double> average_ranks(std::span<const double> x);

/// Per-column sums of the within-row ranks (the Friedman rank sums R_j).
std::vector<double> friedman_rank_sums(const CostMatrix& y);

struct FriedmanTest {
  double statistic = 0.0;  // NaN when every row is a complete tie
  double p_value = 1.0;    // P(chi^2_{k-1} > statistic)
  std::vector<double> rank_sums;
};
/// Friedman rank-sum test with the tie correction (R friedman.test).
FriedmanTest friedman_test(const CostMatrix& y);

/// Outcome of one elimination test over the columns of a matrix.
struct RaceTestOutcome {
  std::vector<bool> keep;       // per column
  std::size_t best = 0;         // column of the best configuration
  bool dropped_any = false;     // irace's flag (true for the two-column dominance rule)
  double p_value = 1.0;
  double critical_difference = 0.0;  // Conover CD (F-test with p < alpha only)
};

/// Friedman test then, if p < 1 - confidence, Conover's post-hoc comparison with the best:
/// keep the best and every column whose rank sum is within the critical difference (the scan
/// in rank-sum order stops at the first that is not). irace `aux2.friedman`.
RaceTestOutcome friedman_conover(const CostMatrix& y, double confidence);

struct WilcoxonTest {
  double statistic = 0.0;  // V: sum of the ranks of the positive differences
  double p_value = 1.0;    // two-sided
  double estimate = 0.0;   // Hodges-Lehmann (pseudo)median of x - y
  bool exact = false;      // exact distribution (n < 50, no ties, no zeros)
};
/// Paired Wilcoxon signed-rank test of x - y as R's wilcox.test(x, y, paired = TRUE,
/// conf.int = TRUE): exact p for n < 50 without ties or zeros, else the normal approximation
/// with continuity and tie correction. In the approximate case the estimate is the root of the
/// uncorrected standardised statistic, found by bisection (R uses uniroot, tol 1e-4; only its
/// sign is used by the race).
WilcoxonTest wilcoxon_signed_rank(std::span<const double> x, std::span<const double> y);

/// P(V <= q) for the signed-rank statistic of n observations (R psignrank).
double psignrank(double q, int n);

/// irace `aux_friedman`: with exactly two columns, a column that is <= the other on every row
/// wins outright (the other is dropped); otherwise the Wilcoxon test decides, the worse being
/// the one the pseudo-median points at. With more columns: friedman_conover.
RaceTestOutcome race_test(const CostMatrix& y, double confidence);

}  // namespace sd::design
