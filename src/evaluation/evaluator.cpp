#include "evaluation/evaluator.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>

#include "evaluation/simulation.hpp"

namespace sd {

ThreadedEvaluator::ThreadedEvaluator(int threads)
    : threads_(threads > 0 ? threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()))) {}

void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t, int)>& body) {
  const int workers = static_cast<int>(std::min<std::size_t>(count, static_cast<std::size_t>(std::max(1, threads))));
  if (workers <= 1) {
    for (std::size_t i = 0; i < count; ++i) body(i, 0);
    return;
  }
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  auto work = [&](int worker) {
    for (std::size_t i; (i = next.fetch_add(1)) < count;) {
      try {
        body(i, worker);
      } catch (...) {
        std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
        next = count;
      }
    }
  };
  std::vector<std::thread> pool;
  for (int w = 1; w < workers; ++w) pool.emplace_back(work, w);
  work(0);
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

void ThreadedEvaluator::evaluate(const Mission& mission, std::span<const EvaluationTask> tasks, std::span<double> scores) {
  // One simulation per worker and per control software, reused across that worker's seeds.
  struct Cached {
    const ControlSoftware* software = nullptr;
    std::unique_ptr<Simulation> simulation;
  };
  std::vector<Cached> cache(static_cast<std::size_t>(threads_));
  parallel_for(tasks.size(), threads_, [&](std::size_t i, int worker) {
    Cached& c = cache[static_cast<std::size_t>(worker)];
    if (c.software != tasks[i].software) {
      c.simulation = std::make_unique<Simulation>(mission, *tasks[i].software);
      c.software = tasks[i].software;
    }
    scores[i] = c.simulation->run(tasks[i].seed);
  });
}

}  // namespace sd
