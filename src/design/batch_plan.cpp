#include "design/batch_plan.hpp"

#include <cmath>

namespace sd::design {

BatchPlan plan_batch(RaceState& s, std::span<const std::size_t> columns, std::size_t k, std::size_t first_test,
                     const RaceEnvironment& env) {
  const std::size_t position = s.position_of(k);
  BatchPlan plan;
  plan.costs.assign(columns.size(), std::nan(""));
  const auto experiment = [&](std::size_t c, std::size_t at) {
    const int id = s.config_ids[c];
    const InstancePosition& inst = env.instances.at(at);
    return Experiment{id, &env.store[id].config, inst.instance, inst.seed, at};
  };
  for (std::size_t e = 0; e < columns.size(); ++e) {
    if (const auto it = s.ahead.find({position, s.config_ids[columns[e]]}); it != s.ahead.end()) {
      plan.costs[e] = it->second;
      s.ahead.erase(it);
      continue;
    }
    plan.experiments.push_back(experiment(columns[e], position));
    plan.step_runs.push_back(e);
  }
  // A run of a configuration eliminated before its step is wasted, but on a worker that would
  // have idled (a race's late steps are as narrow as its few survivors).
  const std::size_t workers = env.runner.parallelism();
  if (plan.experiments.empty()) return plan;
  for (std::size_t later = k + 1; later <= s.n_tasks && later <= k + kMaxInstancesAhead; ++later) {
    if (later > first_test && plan.experiments.size() >= workers) break;
    const std::size_t at = s.position_of(later);
    if (at > env.instances.size()) break;
    for (std::size_t c : columns) {
      const bool known = later <= s.results.size() && !std::isnan(s.results[later - 1][c]);  // an elite's
      if (!known && !s.ahead.count({at, s.config_ids[c]})) plan.experiments.push_back(experiment(c, at));
    }
  }
  return plan;
}

void run_batch(BatchPlan& plan, RaceState& s, RaceEnvironment& env) {
  if (plan.experiments.empty()) return;
  std::vector<double> run(plan.experiments.size(), std::nan(""));
  env.runner.run(plan.experiments, run);
  for (std::size_t i = 0; i < plan.experiments.size(); ++i) {
    if (i < plan.step_runs.size()) plan.costs[plan.step_runs[i]] = run[i];
    else s.ahead[{plan.experiments[i].position, plan.experiments[i].configuration_id}] = run[i];
  }
}

}  // namespace sd::design
