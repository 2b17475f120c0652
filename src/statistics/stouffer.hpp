#pragma once
// Stouffer's method: many independent z-scores (or t's with enough degrees of freedom) combined
// into one, to tell whether a whole group leans one way although no member alone does.
#include <span>

namespace sd::statistics {

struct StoufferTest {
  double z = 0.0;        // the sum of the scores over the square root of their number
  double p_value = 1.0;  // two-sided: R's 2 * pnorm(-abs(z))
};
/// Stouffer's combined z of equally weighted scores, summed in input order. A non-finite score
/// gives a non-finite z (a caller that wants to ignore one passes 0 for it).
/// Throws std::invalid_argument on empty input.
StoufferTest stouffer_z(std::span<const double> z_scores);

}  // namespace sd::statistics
