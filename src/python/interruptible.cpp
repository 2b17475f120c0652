#include "python/interruptible.hpp"

#include <pybind11/pybind11.h>

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>

namespace sd::python {

namespace py = pybind11;

void run_interruptibly(const std::function<void()>& job, const std::function<void()>& cancel,
                       const std::function<void()>& poll) {
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  std::exception_ptr job_error, python_error;
  {
    const py::gil_scoped_release release;
    std::thread worker([&] {
      try {
        job();
      } catch (...) {
        job_error = std::current_exception();
      }
      const std::lock_guard lock(mutex);
      done = true;
      finished.notify_all();
    });
    std::unique_lock lock(mutex);
    while (!done) {
      finished.wait_for(lock, std::chrono::milliseconds(20));
      if (done || python_error) continue;
      lock.unlock();
      {
        const py::gil_scoped_acquire gil;
        try {
          if (PyErr_CheckSignals() != 0) throw py::error_already_set();
          if (poll) poll();
        } catch (...) {
          python_error = std::current_exception();
        }
      }
      if (python_error) cancel();
      lock.lock();
    }
    lock.unlock();
    worker.join();
  }
  if (python_error) std::rethrow_exception(python_error);
  if (poll) poll();  // the last progress, with the GIL
  if (job_error) std::rethrow_exception(job_error);
}

}  // namespace sd::python
