#pragma once
// Assessing control software across the reality gap (Ligot & Birattari 2020): each piece of
// software runs on the same seeds in the design model (the mission's robot model) and in N
// pseudo-reality samples; the result is, per software, the two means, the drop with a 95 %
// confidence interval and a paired test, and for several pieces of software their ranks in
// each world and the rank correlation between worlds (a rank inversion is the reality gap's
// second effect). `swarmdesign assess`, experiments and the web app assess through here.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/cancel_token.hpp"
#include "control/control_software.hpp"
#include "evaluation/evaluator.hpp"
#include "missions/mission.hpp"
#include "reality/pseudo_reality.hpp"

namespace sd::app {

struct SoftwareToAssess {
  std::string label;  // "design 3 best", "software", a saved name ...
  ControlSoftware software;
};

struct AssessRequest {
  std::vector<SoftwareToAssess> software;
  PseudoRealitySpec spec;
  std::string spec_reference;
  std::vector<std::uint64_t> samples;  // pseudo-reality samples, numbered from 1
  std::vector<std::uint64_t> seeds;    // the same seeds in every world
  int threads = 0;
  Evaluator* evaluator = nullptr;      // another backend (MPI); else local threads
  std::function<void(std::size_t done, std::size_t all)> progress;
  const CancelToken* cancel = nullptr; // checked between batches: Cancelled is thrown
};

/// The most runs one assessment may ask for, from any front end (a web page asks for fewer:
/// kMaxDesignAssessmentRuns).
inline constexpr std::size_t kMaxAssessRuns = 10'000'000;
/// The runs the request asks for (each software on each seed, in the design model and in each
/// sample); InvalidRequest past kMaxAssessRuns. assess() checks it before any run.
std::size_t assess_runs(const AssessRequest& request);

struct SoftwareAssessment {
  std::string label, configuration;
  std::vector<double> design_scores;   // per seed
  std::vector<double> reality_scores;  // per sample, then per seed: [sample * seeds + seed]
  double design_mean = 0.0, reality_mean = 0.0;
  /// How much worse it does in the pseudo-realities, in the mission's units (design minus
  /// reality for a maximised mission, reality minus design for a minimised one): positive is
  /// a loss. Its 95 % t interval and the Wilcoxon signed-rank p come from the per-seed pairs
  /// (design-model score, mean over the samples with that seed).
  double drop = 0.0, drop_low = 0.0, drop_high = 0.0;
  double relative_drop = 0.0;          // drop / |design mean|; NaN when that mean is 0
  double p_value = 1.0;
  int design_rank = 0, reality_rank = 0;  // 1 = best, by mean
  std::vector<int> sample_ranks;          // per sample, by mean over its seeds
};

struct Assessment {
  std::string mission, direction, spec_name, spec_reference, spec_digest;
  std::vector<std::uint64_t> samples, seeds;
  std::vector<RobotModel> models;      // per sample
  int distinct_models = 0;             // of the samples: a fixed specification's are all one model, run once
  std::vector<SoftwareAssessment> software;
  /// Spearman's rho between the design-model and the pseudo-reality means (NaN for fewer
  /// than three pieces of software), and the pairs whose order the pseudo-realities invert.
  double rank_correlation = 0.0;
  int inverted_pairs = 0, pairs = 0;
  double seconds = 0.0;
};

struct AssessCancelled : std::runtime_error {
  AssessCancelled() : std::runtime_error("the assessment was cancelled") {}
};

/// InvalidRequest for no software, no seed or no sample.
Assessment assess(const Mission& mission, const AssessRequest& request);

}  // namespace sd::app
