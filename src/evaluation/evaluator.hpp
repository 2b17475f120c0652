#pragma once
// Evaluation behind one interface: the design process, the CLI and (later) MPI ranks or a
// browser request all hand over a batch of (control software, seed) tasks and get one
// score per task. Scores are written by task index, so a batch's result never depends on
// how many workers computed it.
#include <cstdint>
#include <functional>
#include <span>
#include <vector>

#include "control/control_software.hpp"
#include "missions/mission.hpp"

namespace sd {

struct EvaluationTask {
  const ControlSoftware* software;
  std::uint64_t seed;
};

class Evaluator {
 public:
  virtual ~Evaluator() = default;
  /// scores[i] = the mission's natural score of tasks[i].
  virtual void evaluate(const Mission& mission, std::span<const EvaluationTask> tasks, std::span<double> scores) = 0;
};

/// Evaluates on local threads (0 = all cores).
class ThreadedEvaluator : public Evaluator {
 public:
  explicit ThreadedEvaluator(int threads = 0);
  void evaluate(const Mission& mission, std::span<const EvaluationTask> tasks, std::span<double> scores) override;
  int threads() const { return threads_; }

 private:
  int threads_;
};

/// Runs `body(index, worker)` for every index in [0, count) on `threads` threads.
void parallel_for(std::size_t count, int threads, const std::function<void(std::size_t, int)>& body);

}  // namespace sd
