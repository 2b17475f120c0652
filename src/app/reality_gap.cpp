#include "app/reality_gap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "statistics/descriptive.hpp"
#include "statistics/mean_interval.hpp"
#include "statistics/signed_rank.hpp"

namespace sd::app {

RealityGap reality_gap(const std::vector<double>& design_scores, const std::vector<double>& reality_by_seed,
                       double reality_mean, bool maximise) {
  RealityGap g;
  g.design_mean = statistics::mean(design_scores);
  g.reality_mean = reality_mean;
  std::vector<double> losses(design_scores.size());
  for (std::size_t s = 0; s < design_scores.size(); ++s)
    losses[s] = maximise ? design_scores[s] - reality_by_seed[s] : reality_by_seed[s] - design_scores[s];
  const statistics::MeanInterval interval = statistics::t_interval(losses);
  g.drop = maximise ? g.design_mean - g.reality_mean : g.reality_mean - g.design_mean;
  g.drop_low = interval.low;
  g.drop_high = interval.high;
  g.relative_drop = g.design_mean != 0.0 ? g.drop / std::abs(g.design_mean) : std::numeric_limits<double>::quiet_NaN();
  const bool all_zero = std::all_of(losses.begin(), losses.end(), [](double v) { return v == 0.0; });
  g.p_value = all_zero ? 1.0 : statistics::wilcoxon_signed_rank(design_scores, reality_by_seed).p_value;
  return g;
}

}  // namespace sd::app
