#include "app/evaluation_job.hpp"

#include <algorithm>
#include <fstream>
#include <optional>
#include <span>

#include "evaluation/simulation.hpp"
#include "evaluation/trace_writer.hpp"

namespace sd::app {

std::vector<double> score_seeds(const Mission& mission, const ControlSoftware& software,
                                const std::vector<std::uint64_t>& seeds, const ScoreOptions& options) {
  std::vector<double> scores(seeds.size());
  std::unique_ptr<Evaluator> own;
  Evaluator& evaluator = options.evaluator ? *options.evaluator : *(own = make_evaluator(options.threads));
  std::vector<EvaluationTask> tasks;
  tasks.reserve(tasks.size() + seeds.size());
  for (const auto s : seeds) tasks.push_back({&software, s, 0});
  const std::size_t batch = options.progress ? static_cast<std::size_t>(std::max(1, evaluator.workers()) * 4) : tasks.size();
  for (std::size_t start = 0; start < tasks.size(); start += batch) {
    const std::size_t count = std::min(batch, tasks.size() - start);
    evaluator.evaluate(mission, std::span(tasks).subspan(start, count), std::span(scores).subspan(start, count));
    if (options.progress) options.progress(start + count, tasks.size());
  }
  return scores;
}

double traced_run(const Mission& mission, const ControlSoftware& software, std::uint64_t seed,
                  const std::filesystem::path& trace) {
  std::ofstream out(trace);
  if (!out) throw std::runtime_error("cannot write the trace file " + trace.string());
  TraceWriter writer(out);
  return observed_run(mission, software, seed, writer);
}

double observed_run(const Mission& mission, const ControlSoftware& software, std::uint64_t seed,
                    TickObserver& observer) {
  Simulation simulation(mission, software);
  return simulation.run(seed, &observer);
}

}  // namespace sd::app
