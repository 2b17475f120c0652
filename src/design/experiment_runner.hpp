#pragma once
// How the optimiser gets costs: a race step hands over a batch of experiments (every alive
// configuration that still needs a result on one instance) and receives one cost per experiment,
// stored by index. Lower cost is better; +/-Inf rejects the configuration (irace 3.x).
#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>

#include "design/parameter_space.hpp"

namespace sd::design {

struct Experiment {
  int configuration_id = 0;                     // 1, 2, ... (irace .ID.)
  const Configuration* configuration = nullptr;
  std::size_t instance = 0;                     // index into the caller's instance list (0-based)
  std::uint64_t seed = 0;                       // 1 .. 2^31-1, one per instance-list position
  std::size_t position = 0;                     // position in the instance list (1-based)
};

class ExperimentRunner {
 public:
  virtual ~ExperimentRunner() = default;
  /// Evaluates every experiment; costs[i] belongs to experiments[i]. May throw.
  virtual void run(std::span<const Experiment> experiments, std::span<double> costs) = 0;
  /// Experiments it runs at once (threads, MPI ranks): a race fills a narrower step up to it
  /// with the same configurations' runs on the next instances (race.cpp).
  virtual std::size_t parallelism() const { return 1; }
};

/// Evaluates a batch on T workers of the process's Executor (a cost function with no simulator
/// behind it: the optimiser's tests). Each result is written to its own slot, so the outcome
/// never depends on the thread count provided the cost function is a pure function of its
/// experiment (configuration, instance, seed).
class ThreadedRunner final : public ExperimentRunner {
 public:
  using CostFunction = std::function<double(const Experiment&)>;
  /// threads == 0: one per hardware thread.
  explicit ThreadedRunner(CostFunction cost, unsigned threads = 0);
  void run(std::span<const Experiment> experiments, std::span<double> costs) override;
  std::size_t parallelism() const override { return threads_; }
  unsigned threads() const { return threads_; }

 private:
  CostFunction cost_;
  unsigned threads_;
};

}  // namespace sd::design
