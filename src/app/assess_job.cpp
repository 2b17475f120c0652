#include "app/assess_job.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <span>

#include "app/errors.hpp"
#include "app/reality_gap.hpp"
#include "control/config_string.hpp"
#include "statistics/correlation.hpp"
#include "statistics/descriptive.hpp"
#include "statistics/mean_interval.hpp"
#include "statistics/ranks.hpp"
#include "statistics/signed_rank.hpp"

namespace sd::app {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Ranks 1 = best of `means` (ties share the better rank's average, rounded down).
std::vector<int> ranks_of(const std::vector<double>& means, bool maximise) {
  std::vector<double> keys(means.size());
  for (std::size_t i = 0; i < means.size(); ++i) keys[i] = maximise ? -means[i] : means[i];
  const std::vector<double> r = statistics::average_ranks(keys);
  std::vector<int> out(r.size());
  for (std::size_t i = 0; i < r.size(); ++i) out[i] = static_cast<int>(std::floor(r[i]));
  return out;
}

void summarise(SoftwareAssessment& a, std::size_t samples, std::size_t seeds, bool maximise) {
  // Per seed: the mean over the samples run with that seed.
  std::vector<double> reality_by_seed(seeds, 0.0);
  for (std::size_t k = 0; k < samples; ++k)
    for (std::size_t s = 0; s < seeds; ++s) reality_by_seed[s] += a.reality_scores[k * seeds + s] / static_cast<double>(samples);
  const RealityGap g = reality_gap(a.design_scores, reality_by_seed, statistics::mean(a.reality_scores), maximise);
  a.design_mean = g.design_mean;
  a.reality_mean = g.reality_mean;
  a.drop = g.drop;
  a.drop_low = g.drop_low;
  a.drop_high = g.drop_high;
  a.relative_drop = g.relative_drop;
  a.p_value = g.p_value;
}

}  // namespace

std::size_t assess_runs(const AssessRequest& request) {
  const std::size_t runs = request.software.size() * request.seeds.size() * (1 + request.samples.size());
  if (runs > kMaxAssessRuns) throw InvalidRequest("assess: " + std::to_string(runs) + " runs; at most 10,000,000 at once");
  return runs;
}

namespace {

/// Every knob alike, bit for bit: the runs of one are the runs of the other.
bool same_model(const RobotModel& a, const RobotModel& b) {
  return std::all_of(kRobotKnobs.begin(), kRobotKnobs.end(), [&](const RobotKnob& k) { return a.*(k.member) == b.*(k.member); });
}

}  // namespace

Assessment assess(const Mission& mission, const AssessRequest& request) {
  if (request.software.empty()) throw InvalidRequest("assess: no control software to assess");
  if (request.seeds.empty()) throw InvalidRequest("assess: no seed");
  if (request.samples.empty()) throw InvalidRequest("assess: no pseudo-reality sample");
  assess_runs(request);
  const auto start = std::chrono::steady_clock::now();
  const bool maximise = mission.objective.direction == Direction::Maximize;
  const std::size_t n_software = request.software.size(), n_samples = request.samples.size(), n_seeds = request.seeds.size();

  Assessment out;
  out.mission = mission.name;
  out.direction = std::string(direction_name(mission.objective.direction));
  out.spec_name = request.spec.name;
  out.spec_reference = request.spec_reference;
  out.spec_digest = request.spec.digest;
  out.samples = request.samples;
  out.seeds = request.seeds;
  for (const std::uint64_t k : request.samples) out.models.push_back(request.spec.sample(mission.robot, k));
  // Samples that are the same model (a fixed specification's are all one) give the same runs:
  // each model runs once and its scores stand for every sample that is it.
  std::vector<std::size_t> model_of(n_samples);  // sample k's index into `distinct`
  std::vector<const RobotModel*> distinct;
  for (std::size_t k = 0; k < n_samples; ++k) {
    const auto same = std::find_if(distinct.begin(), distinct.end(), [&](const RobotModel* m) { return same_model(*m, out.models[k]); });
    model_of[k] = static_cast<std::size_t>(same - distinct.begin());
    if (same == distinct.end()) distinct.push_back(&out.models[k]);
  }
  out.distinct_models = static_cast<int>(distinct.size());

  // Per software: its seeds in the design model, then each distinct model's. The key promises
  // the evaluator the same software across batches, so its simulations are built once.
  const std::size_t per_software = n_seeds * (1 + n_samples);
  const std::size_t runs_per_software = n_seeds * (1 + distinct.size());
  std::vector<EvaluationTask> tasks;
  tasks.reserve(n_software * runs_per_software);
  for (std::size_t i = 0; i < n_software; ++i) {
    const ControlSoftware* software = &request.software[i].software;
    const auto key = static_cast<std::int64_t>(i);
    for (const std::uint64_t seed : request.seeds) tasks.push_back({software, seed, key, nullptr});
    for (const RobotModel* model : distinct)
      for (const std::uint64_t seed : request.seeds) tasks.push_back({software, seed, key, model});
  }
  std::vector<double> ran(tasks.size());
  std::unique_ptr<Evaluator> own;
  Evaluator& evaluator = request.evaluator ? *request.evaluator : *(own = make_evaluator(request.threads));
  const bool batched = request.progress || request.cancel;
  const std::size_t batch = batched ? static_cast<std::size_t>(std::max(1, evaluator.workers()) * 8) : tasks.size();
  for (std::size_t first = 0; first < tasks.size(); first += batch) {
    if (request.cancel && request.cancel->cancelled()) throw AssessCancelled();
    const std::size_t count = std::min(batch, tasks.size() - first);
    evaluator.evaluate(mission, std::span(tasks).subspan(first, count), std::span(ran).subspan(first, count));
    if (request.progress) request.progress(first + count, tasks.size());
  }
  // Every sample's runs, in the order of the request: the design model's, then sample by sample.
  std::vector<double> scores(n_software * per_software);
  for (std::size_t i = 0; i < n_software; ++i) {
    const double* from = ran.data() + i * runs_per_software;
    double* to = scores.data() + i * per_software;
    std::copy(from, from + n_seeds, to);
    for (std::size_t k = 0; k < n_samples; ++k)
      std::copy(from + n_seeds * (1 + model_of[k]), from + n_seeds * (2 + model_of[k]), to + n_seeds * (1 + k));
  }

  std::vector<double> design_means, reality_means;
  for (std::size_t i = 0; i < n_software; ++i) {
    SoftwareAssessment a;
    a.label = request.software[i].label;
    a.configuration = to_config_string(request.software[i].software);
    const auto* base = scores.data() + i * per_software;
    a.design_scores.assign(base, base + n_seeds);
    a.reality_scores.assign(base + n_seeds, base + per_software);
    summarise(a, n_samples, n_seeds, maximise);
    design_means.push_back(a.design_mean);
    reality_means.push_back(a.reality_mean);
    out.software.push_back(std::move(a));
  }
  const std::vector<int> design_ranks = ranks_of(design_means, maximise), reality_ranks = ranks_of(reality_means, maximise);
  for (std::size_t k = 0; k < n_samples; ++k) {
    std::vector<double> sample_means(n_software);
    for (std::size_t i = 0; i < n_software; ++i)
      sample_means[i] = statistics::mean(std::span(out.software[i].reality_scores).subspan(k * n_seeds, n_seeds));
    const std::vector<int> r = ranks_of(sample_means, maximise);
    for (std::size_t i = 0; i < n_software; ++i) out.software[i].sample_ranks.push_back(r[i]);
  }
  for (std::size_t i = 0; i < n_software; ++i) {
    out.software[i].design_rank = design_ranks[i];
    out.software[i].reality_rank = reality_ranks[i];
    for (std::size_t j = i + 1; j < n_software; ++j) {
      ++out.pairs;
      const double before = design_means[i] - design_means[j], after = reality_means[i] - reality_means[j];
      if (before * after < 0.0) ++out.inverted_pairs;
    }
  }
  out.rank_correlation = n_software >= 3 ? statistics::spearman_rho(design_means, reality_means) : kNaN;
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace sd::app
