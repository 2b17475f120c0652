#pragma once
// How a front end stops a running job (a design, an evolution, an experiment) from another
// thread: the job looks at the token between two durable steps, so what it stops is resumable.
#include <atomic>

namespace sd::app {

class CancelToken {
 public:
  void cancel() { cancelled_.store(true); }
  bool cancelled() const { return cancelled_.load(); }

 private:
  std::atomic<bool> cancelled_{false};
};

}  // namespace sd::app
