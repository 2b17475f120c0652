#include "cli/score_report.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <numeric>
#include <span>

#include "control/config_string.hpp"
#include "evaluation/evaluator.hpp"

namespace sd::cli {

namespace {
double median_of(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}
}  // namespace

std::vector<double> score_seeds(const Mission& mission, const ControlSoftware& software,
                                const std::vector<std::uint64_t>& seeds, int threads, bool progress) {
  std::vector<double> scores(seeds.size());
  ThreadedEvaluator evaluator(threads);
  std::vector<EvaluationTask> tasks;
  for (const auto s : seeds) tasks.push_back({&software, s});
  progress = progress && seeds.size() > 1;
  // Batches keep a progress line alive without changing any score.
  const std::size_t batch = progress ? static_cast<std::size_t>(std::max(1, evaluator.threads()) * 4) : tasks.size();
  for (std::size_t start = 0; start < tasks.size(); start += batch) {
    const std::size_t count = std::min(batch, tasks.size() - start);
    evaluator.evaluate(mission, std::span(tasks).subspan(start, count), std::span(scores).subspan(start, count));
    if (progress) std::fprintf(stderr, "\revaluated %zu/%zu seeds", start + count, tasks.size());
  }
  if (progress) std::fprintf(stderr, "\r\033[K");
  return scores;
}

void print_scores(const Mission& mission, const ControlSoftware& software, const std::vector<std::uint64_t>& seeds,
                  const std::vector<double>& scores, bool json) {
  const double mean = std::accumulate(scores.begin(), scores.end(), 0.0) / static_cast<double>(scores.size());
  const double median = median_of(scores);
  if (json) {
    nlohmann::json runs = nlohmann::json::array();
    for (std::size_t i = 0; i < seeds.size(); ++i) runs.push_back({{"seed", seeds[i]}, {"score", scores[i]}});
    nlohmann::json out{{"mission", mission.name}, {"direction", direction_name(mission.objective.direction)},
                       {"control_software", to_config_string(software)}, {"runs", runs}};
    if (seeds.size() > 1) {
      out["mean"] = mean;
      out["median"] = median;
    }
    std::cout << out.dump(2) << "\n";
    return;
  }
  for (std::size_t i = 0; i < seeds.size(); ++i) std::cout << "Score " << format_number(scores[i]) << "\n";
  if (seeds.size() > 1) std::cout << "Mean " << format_number(mean) << "\nMedian " << format_number(median) << "\n";
}

}  // namespace sd::cli
