#pragma once
// One pool of worker threads per process, shared by every job that runs in it: a design, an
// `evaluate --seeds`, an evolution, and (in a server) several of them at once. A job asks for
// up to W workers; the pool never holds more threads than the largest W asked, so two jobs
// that each ask for all cores share the cores instead of oversubscribing them.
//
//   Executor::shared().run(tasks.size(), threads, [&](std::size_t i, unsigned slot) { ... });
//
// Work is handed out one index at a time (runs differ in length) and every result goes to its
// own index, so what a batch computes never depends on the number of workers or on which
// thread ran which index.
#include <condition_variable>
#include <cstddef>
#include <functional>
#include <list>
#include <mutex>
#include <thread>
#include <vector>

namespace sd {

/// The one rule for a thread count: 0 means one per core (at least one).
unsigned resolve_threads(unsigned requested);
inline int resolve_threads(int requested) {
  return static_cast<int>(resolve_threads(static_cast<unsigned>(requested > 0 ? requested : 0)));
}

class Executor {
 public:
  /// body(index, slot): slot is in [0, workers) and no two threads hold the same slot of a batch
  /// at once, so a caller may keep per-slot scratch (a cached simulation, say).
  using Body = std::function<void(std::size_t index, unsigned slot)>;

  /// The process's pool (created on first use).
  static Executor& shared();

  Executor() = default;
  ~Executor();
  Executor(const Executor&) = delete;
  Executor& operator=(const Executor&) = delete;

  /// Runs body for every index in [0, count) on at most `workers` threads (0: one per core)
  /// and returns when all are done. The first exception stops handing out indices and is
  /// rethrown here. Called from inside a pool thread, it runs inline (no deadlock).
  void run(std::size_t count, unsigned workers, const Body& body);

  /// Threads in the pool now (for tests and diagnostics).
  std::size_t size() const;

  /// The pool's threads run at this niceness (Linux, per thread; 0 by default), each taking it
  /// before its next batch. A server raises it so that the cores go to its requests first (a
  /// sign-in's Argon2id check, a status read) and the designs take what is left: they only
  /// wait, they compute the same.
  void set_worker_niceness(int niceness);
  /// The niceness of the calling thread (for tests).
  static int thread_niceness();

 private:
  struct Batch;
  void grow_to(std::size_t threads);  // with mutex_ held
  void work();
  Batch* pick();                      // with mutex_ held: a batch with an index and a free slot

  mutable std::mutex mutex_;
  std::condition_variable work_ready_, batch_done_;
  std::list<Batch*> queue_;           // oldest first: batches are served in arrival order
  std::vector<std::thread> threads_;
  bool stopping_ = false;
  int niceness_ = 0;
};

}  // namespace sd
