#pragma once
// A long job (an evaluation, a trace, a design) run from Python: on a thread of its own with
// the GIL released, so that other Python threads run meanwhile, while the calling thread wakes
// every few milliseconds to run Python's signal handlers (Ctrl-C) and the caller's `poll`
// (progress callbacks) with the GIL held. When a handler or `poll` raises, `cancel` asks the
// job to stop; once it has, that Python exception (KeyboardInterrupt, say) is raised.
#include <functional>

namespace sd::python {

void run_interruptibly(const std::function<void()>& job, const std::function<void()>& cancel,
                       const std::function<void()>& poll = {});

/// Thrown inside a job to stop it when it was asked to (caught by nobody but the job's thread).
struct JobCancelled {};

}  // namespace sd::python
