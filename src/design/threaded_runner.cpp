#include <stdexcept>

#include "core/executor.hpp"
#include "design/experiment_runner.hpp"

namespace sd::design {

ThreadedRunner::ThreadedRunner(CostFunction cost, unsigned threads) : cost_(std::move(cost)), threads_(resolve_threads(threads)) {
  if (!cost_) throw std::invalid_argument("ThreadedRunner needs a cost function");
}

void ThreadedRunner::run(std::span<const Experiment> experiments, std::span<double> costs) {
  if (costs.size() != experiments.size()) throw std::invalid_argument("ThreadedRunner: costs size mismatch");
  // The slot an experiment writes to is fixed by its index, never by the thread that ran it.
  Executor::shared().run(experiments.size(), threads_,
                         [&](std::size_t i, unsigned) { costs[i] = cost_(experiments[i]); });
}

}  // namespace sd::design
