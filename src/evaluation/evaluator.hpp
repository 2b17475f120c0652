#pragma once
// The evaluation seam: every caller — a design's races, `evaluate --seeds`, an evolution, a web
// request — hands over a batch of (control software, seed) tasks and gets one score per task,
// by index. Local threads implement it now; MPI ranks implement the same interface. Scores are
// written by task index, so a batch's result never depends on how many workers computed it or
// which worker computed which task.
#include <atomic>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include "control/control_software.hpp"
#include "missions/mission.hpp"

namespace sd {

class Simulation;

struct EvaluationTask {
  const ControlSoftware* software = nullptr;
  std::uint64_t seed = 0;
  /// Tasks with the same key ≥ 0 carry the same control software, in this batch and in the
  /// next batches of the same evaluator (a design's configuration id), so a backend may keep
  /// their simulation built between batches. -1: no such promise.
  std::int64_t key = -1;
  /// The robot model of this run: a pseudo-reality (reality/); null: the mission's own.
  const RobotModel* robot = nullptr;
};

/// evaluate() saw its stop flag raised and left some tasks unscored: the whole batch is void
/// (a design drops the step and resumes from its last durable one).
struct EvaluationStopped : std::runtime_error {
  EvaluationStopped() : std::runtime_error("the evaluation was stopped") {}
};

class Evaluator {
 public:
  virtual ~Evaluator() = default;
  /// scores[i] = the mission's natural score of tasks[i]. One caller at a time.
  virtual void evaluate(const Mission& mission, std::span<const EvaluationTask> tasks, std::span<double> scores) = 0;
  /// Workers it evaluates with (for reports).
  virtual int workers() const = 0;
  /// While `flag` is set and raised, a batch stops between two runs and evaluate() throws
  /// EvaluationStopped, so a cancel is heard within one run rather than one batch (a race step
  /// at a large budget is a minute). On MPI ranks, between two chunks of a few runs. nullptr:
  /// no flag.
  void stop_when(const std::atomic<bool>* flag) { stop_ = flag; }

 protected:
  bool stop_requested() const { return stop_ != nullptr && stop_->load(std::memory_order_relaxed); }
  /// For a backend that hands batches on to another evaluator (MPI's rank 0 to its threads).
  const std::atomic<bool>* stop_flag() const { return stop_; }

 private:
  const std::atomic<bool>* stop_ = nullptr;
};

/// Evaluates on up to `threads` workers of the process's Executor (0: one per core). Keeps,
/// per worker, the simulations of the keyed control software of the last batch.
class ThreadedEvaluator final : public Evaluator {
 public:
  explicit ThreadedEvaluator(int threads = 0);
  ~ThreadedEvaluator() override;
  void evaluate(const Mission& mission, std::span<const EvaluationTask> tasks, std::span<double> scores) override;
  int workers() const override { return threads_; }
  int threads() const { return threads_; }

 private:
  struct Slot {
    std::unordered_map<std::int64_t, std::unique_ptr<Simulation>> keyed;
    const ControlSoftware* unkeyed_software = nullptr;  // this batch only
    std::unique_ptr<Simulation> unkeyed;
  };
  int threads_;
  const Mission* mission_ = nullptr;  // of the cached simulations
  std::string mission_digest_;
  std::vector<Slot> slots_;
};

/// The evaluator a job uses when its caller brings none: local threads, unless the process
/// installed another backend at start-up (a process started by mpirun installs MPI ranks), so
/// that every job — designs, `evaluate --seeds`, evolutions, experiments — spreads over the
/// machines it was launched on without knowing how.
std::unique_ptr<Evaluator> make_evaluator(int threads = 0);
using EvaluatorFactory = std::function<std::unique_ptr<Evaluator>(int threads)>;
/// Installs the process's backend (empty: back to local threads). Call before jobs start.
void set_evaluator_factory(EvaluatorFactory factory);

}  // namespace sd
