#include "core/executor.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <exception>

namespace sd {

namespace {
thread_local bool inside_pool = false;
}

unsigned resolve_threads(unsigned requested) {
  return requested > 0 ? requested : std::max(1u, std::thread::hardware_concurrency());
}

struct Executor::Batch {
  std::size_t count = 0;
  unsigned workers = 1;
  const Body* body = nullptr;
  std::size_t next = 0;       // next index to hand out
  std::size_t running = 0;    // indices handed out and not yet finished
  unsigned slots_taken = 0;   // threads that joined this batch
  std::exception_ptr error;
  bool complete() const { return next >= count && running == 0; }
};

Executor& Executor::shared() {
  static Executor pool;
  return pool;
}

Executor::~Executor() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  work_ready_.notify_all();
  for (auto& thread : threads_) thread.join();
}

std::size_t Executor::size() const {
  std::lock_guard lock(mutex_);
  return threads_.size();
}

void Executor::grow_to(std::size_t threads) {
  while (threads_.size() < threads) threads_.emplace_back([this] { work(); });
}

Executor::Batch* Executor::pick() {
  for (Batch* batch : queue_)
    if (batch->next < batch->count && batch->slots_taken < batch->workers) return batch;
  return nullptr;
}

void Executor::set_worker_niceness(int niceness) {
  std::lock_guard lock(mutex_);
  niceness_ = niceness;
}

int Executor::thread_niceness() {
  return getpriority(PRIO_PROCESS, static_cast<id_t>(gettid()));
}

void Executor::work() {
  inside_pool = true;
  int niceness = 0;
  std::unique_lock lock(mutex_);
  while (true) {
    work_ready_.wait(lock, [&] { return stopping_ || pick() != nullptr; });
    if (stopping_) return;
    if (niceness != niceness_) {
      // Linux gives each thread its own niceness (a POSIX process would share one). Lowering it
      // back needs CAP_SYS_NICE; without, the thread keeps the lower priority, which is harmless.
      niceness = niceness_;
      setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), niceness);
    }
    Batch& batch = *pick();
    const unsigned slot = batch.slots_taken++;
    // Stay with this batch until it has no index left: the slot is ours until then.
    while (batch.next < batch.count) {
      const std::size_t index = batch.next++;
      ++batch.running;
      lock.unlock();
      std::exception_ptr error;
      try {
        (*batch.body)(index, slot);
      } catch (...) {
        error = std::current_exception();
      }
      lock.lock();
      --batch.running;
      if (error) {
        if (!batch.error) batch.error = error;
        batch.next = batch.count;  // hand out nothing more
      }
    }
    if (batch.complete()) batch_done_.notify_all();
  }
}

void Executor::run(std::size_t count, unsigned workers, const Body& body) {
  if (count == 0) return;
  workers = static_cast<unsigned>(std::min<std::size_t>(resolve_threads(workers), count));
  if (inside_pool) {  // a job started by a pool thread: its own thread is its only worker
    for (std::size_t i = 0; i < count; ++i) body(i, 0);
    return;
  }
  Batch batch;
  batch.count = count;
  batch.workers = workers;
  batch.body = &body;
  std::unique_lock lock(mutex_);
  grow_to(workers);
  queue_.push_back(&batch);
  work_ready_.notify_all();
  batch_done_.wait(lock, [&] { return batch.complete(); });
  queue_.remove(&batch);
  lock.unlock();
  if (batch.error) std::rethrow_exception(batch.error);
}

}  // namespace sd
