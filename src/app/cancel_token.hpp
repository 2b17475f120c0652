#pragma once
// How a front end stops a running job (a design, an evolution, an experiment) from another
// thread: the job looks at the token between two durable steps, so what it stops is resumable;
// a design's evaluator also looks at it between two runs and drops the step it was in.
#include <atomic>

namespace sd::app {

class CancelToken {
 public:
  void cancel() { cancelled_.store(true); }
  bool cancelled() const { return cancelled_.load(); }
  /// For an evaluator to stop a batch between two runs (Evaluator::stop_when).
  const std::atomic<bool>& flag() const { return cancelled_; }

 private:
  std::atomic<bool> cancelled_{false};
};

}  // namespace sd::app
