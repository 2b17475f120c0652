#pragma once
// Which configurations one elimination test of an F-race keeps (irace 3.5 R/race.R:
// aux2.friedman, aux_friedman). The statistics themselves live in statistics/.
#include <cstddef>
#include <vector>

#include "statistics/friedman.hpp"

namespace sd::design {

// The race's matrices and rank sums are the statistics library's; the race names them as its own.
using statistics::CostMatrix;
using statistics::friedman_rank_sums;

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

/// irace `aux_friedman`: with exactly two columns, a column that is <= the other on every row
/// wins outright (the other is dropped); otherwise the Wilcoxon signed-rank test decides, the
/// worse being the one the pseudo-median points at. With more columns: friedman_conover.
RaceTestOutcome race_test(const CostMatrix& y, double confidence);

}  // namespace sd::design
