#pragma once
// The reality gap of one piece of control software, one rule for assess (assess_job) and for an
// experiment's report (experiment_report): its scores in the design model against those in the
// pseudo-realities, paired by seed (the design-model run against the mean over the samples run
// with that seed). The drop is positive for a loss, whatever the objective's direction.
#include <vector>

namespace sd::app {

struct RealityGap {
  double design_mean = 0.0, reality_mean = 0.0;
  double drop = 0.0;                  // mean loss from the design model to the pseudo-realities
  double drop_low = 0.0, drop_high = 0.0;  // its 95 % t interval over the per-seed losses
  double relative_drop = 0.0;         // drop / |design mean|; NaN when the design mean is 0
  double p_value = 1.0;               // paired Wilcoxon signed-rank; 1 when no seed loses or gains
};

/// design_scores[s] and reality_by_seed[s] per seed s; reality_mean over every pseudo-reality run.
RealityGap reality_gap(const std::vector<double>& design_scores, const std::vector<double>& reality_by_seed,
                       double reality_mean, bool maximise);

}  // namespace sd::app
