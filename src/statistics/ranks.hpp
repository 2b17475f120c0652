#pragma once
// Ranks as R's rank() gives them, and the tie term every rank test corrects its variance with.
#include <span>
#include <vector>

namespace sd::statistics {

/// R's rank(x): 1-based ranks, ties get the average of the ranks they span. Empty input gives
/// no ranks. Values must not be NaN (not checked: a NaN compares unequal to everything).
std::vector<double> average_ranks(std::span<const double> x);

/// Sum over the groups of equal values of t^3 - t, t being the group's size: the tie correction
/// of the Friedman, signed-rank and rank-sum tests. 0 without ties and on empty input. An
/// integer held exactly, so the order in which rows or groups are summed never changes it.
double tie_term(std::span<const double> x);

}  // namespace sd::statistics
