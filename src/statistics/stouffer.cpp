#include "statistics/stouffer.hpp"

#include <cmath>
#include <numeric>
#include <stdexcept>

namespace sd::statistics {

StoufferTest stouffer_z(std::span<const double> z_scores) {
  if (z_scores.empty()) throw std::invalid_argument("stouffer_z: no scores");
  StoufferTest out;
  out.z = std::accumulate(z_scores.begin(), z_scores.end(), 0.0) / std::sqrt(static_cast<double>(z_scores.size()));
  // The standard normal's two-sided tail: P(|Z| > |z|) = erfc(|z| / sqrt 2).
  out.p_value = std::erfc(std::abs(out.z) / std::sqrt(2.0));
  return out;
}

}  // namespace sd::statistics
