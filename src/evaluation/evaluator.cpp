#include "evaluation/evaluator.hpp"

#include <unordered_set>

#include "core/executor.hpp"
#include "evaluation/simulation.hpp"

namespace sd {

namespace {
EvaluatorFactory& installed_factory() {
  static EvaluatorFactory factory;
  return factory;
}
}  // namespace

std::unique_ptr<Evaluator> make_evaluator(int threads) {
  if (const auto& factory = installed_factory()) return factory(threads);
  return std::make_unique<ThreadedEvaluator>(threads);
}

void set_evaluator_factory(EvaluatorFactory factory) { installed_factory() = std::move(factory); }

ThreadedEvaluator::ThreadedEvaluator(int threads)
    : threads_(resolve_threads(threads)),
      slots_(static_cast<std::size_t>(threads_)) {}

ThreadedEvaluator::~ThreadedEvaluator() = default;

void ThreadedEvaluator::evaluate(const Mission& mission, std::span<const EvaluationTask> tasks, std::span<double> scores) {
  // Keep only the simulations this batch can use, so memory follows the batch, not the job.
  std::unordered_set<std::int64_t> keys;
  for (const auto& task : tasks)
    if (task.key >= 0) keys.insert(task.key);
  for (Slot& slot : slots_) {
    if (mission_ != &mission || mission_digest_ != mission.digest) slot.keyed.clear();
    else std::erase_if(slot.keyed, [&](const auto& entry) { return !keys.count(entry.first); });
    slot.unkeyed_software = nullptr;
    slot.unkeyed.reset();
  }
  mission_ = &mission;
  mission_digest_ = mission.digest;
  std::atomic<bool> stopped{false};
  Executor::shared().run(tasks.size(), static_cast<unsigned>(threads_), [&](std::size_t i, unsigned worker) {
    if (stop_requested()) {  // the rest of the batch is skipped: each worker's next task ends at once
      stopped.store(true, std::memory_order_relaxed);
      return;
    }
    Slot& slot = slots_[worker];
    const EvaluationTask& task = tasks[i];
    Simulation* simulation;
    if (task.key >= 0) {
      auto& cached = slot.keyed[task.key];
      if (!cached) cached = std::make_unique<Simulation>(mission, *task.software);
      simulation = cached.get();
    } else {
      if (slot.unkeyed_software != task.software) {
        slot.unkeyed = std::make_unique<Simulation>(mission, *task.software);
        slot.unkeyed_software = task.software;
      }
      simulation = slot.unkeyed.get();
    }
    scores[i] = simulation->run(task.seed, nullptr, task.robot);
  });
  if (stopped.load()) throw EvaluationStopped();
}

}  // namespace sd
