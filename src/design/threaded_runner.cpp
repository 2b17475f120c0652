#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "design/experiment_runner.hpp"

namespace sd::design {

ThreadedRunner::ThreadedRunner(CostFunction cost, unsigned threads) : cost_(std::move(cost)), threads_(threads) {
  if (!cost_) throw std::invalid_argument("ThreadedRunner needs a cost function");
  if (threads_ == 0) threads_ = std::max(1u, std::thread::hardware_concurrency());
}

void ThreadedRunner::run(std::span<const Experiment> experiments, std::span<double> costs) {
  if (costs.size() != experiments.size()) throw std::invalid_argument("ThreadedRunner: costs size mismatch");
  const std::size_t n = experiments.size();
  // Work is handed out one experiment at a time (simulations differ in length); the slot an
  // experiment writes to is fixed by its index, never by the thread that ran it.
  std::atomic<std::size_t> next{0};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  auto work = [&] {
    for (std::size_t i = next++; i < n; i = next++) {
      try {
        costs[i] = cost_(experiments[i]);
      } catch (...) {
        std::lock_guard lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        next = n;
      }
    }
  };
  const std::size_t helpers = std::min<std::size_t>(threads_, n) > 0 ? std::min<std::size_t>(threads_, n) - 1 : 0;
  std::vector<std::thread> pool;
  pool.reserve(helpers);
  for (std::size_t t = 0; t < helpers; ++t) pool.emplace_back(work);
  work();
  for (auto& th : pool) th.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace sd::design
