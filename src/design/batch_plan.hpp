#pragma once
// Which runs go to the workers now (irace's `execute.experiments` call inside `race`, widened):
// a race step's own runs, plus runs of the same configurations on the next instances when
// workers would otherwise idle. The race (race.hpp) decides what must be run; this file only
// decides when. Runs are deterministic, so the race, its results and their order are the same
// as step by step, whatever the number of workers.
#include <cstddef>
#include <span>
#include <vector>

#include "design/race.hpp"

namespace sd::design {

/// How many instances ahead of the current one a batch may reach for: enough to fill idle
/// workers on a race's narrowest steps, few enough that little is wasted when the race ends.
inline constexpr std::size_t kMaxInstancesAhead = 8;

struct BatchPlan {
  std::vector<Experiment> experiments;   // the step's runs first, then the runs ahead
  std::vector<std::size_t> step_runs;    // for each of the step's runs: its index in `columns`
  std::vector<double> costs;             // per column: taken from RaceState::ahead, NaN until run
};

/// The runs task `task` needs for `columns` (the configurations the step runs): those already
/// run ahead are taken out of state.ahead; the others are planned with, before the first test
/// (nothing can be eliminated before it) or while the batch is narrower than the runner's
/// workers, runs on up to kMaxInstancesAhead later instances.
BatchPlan plan_batch(RaceState& state, std::span<const std::size_t> columns, std::size_t task, std::size_t first_test,
                     const RaceEnvironment& env);

/// Runs the plan on env.runner: the step's costs into plan.costs, the others kept in
/// state.ahead until their step takes them.
void run_batch(BatchPlan& plan, RaceState& state, RaceEnvironment& env);

}  // namespace sd::design
