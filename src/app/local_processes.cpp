#include "app/local_processes.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <iostream>
#include <stdexcept>
#include <thread>

#include "app/errors.hpp"
#include "storage/lease.hpp"

namespace sd::app {

StartedDesign LocalProcesses::start(Home& home, const storage::User& user, const DesignLaunch& launch) {
  if (launch.slurm.given())
    throw InvalidRequest("--nodes, --ntasks, --cpus-per-task, --time, --partition and --account are for a cluster project; "
                         "this one runs on this machine");
  // A forked child would leave the MPI job behind: mpirun waits for rank 0 anyway.
  if (launch.detach && launch.mpi_ranks > 1)
    throw InvalidRequest("--detach cannot be used under mpirun (mpirun waits for its ranks); leave it out");
  ProjectDesignRequest request = launch.design;
  request.owner = storage::owner_text(storage::local_process());
  ProjectDesign d = start_project_design(home, user, request);
  StartedDesign out{d.project, d.design, d.resumed, d.abandoned, d.prepared.choice.notes, std::nullopt, false, 0,
                    std::nullopt, "this machine"};
  out.run_here = std::move(d);
  return out;
}

void LocalProcesses::detach(StartedDesign& started) {
  ProjectDesign& d = *started.run_here;
  const auto log = d.design.folder / "design.log";
  std::cout << std::flush;
  std::fflush(nullptr);
  const pid_t child = ::fork();
  if (child < 0) throw std::runtime_error("cannot start the background process");
  if (child == 0) {
    ::setsid();
    std::signal(SIGHUP, SIG_IGN);
    const int null_fd = ::open("/dev/null", O_RDONLY);
    const int log_fd = ::open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0600);
    if (null_fd < 0 || log_fd < 0) std::_Exit(1);
    ::dup2(null_fd, STDIN_FILENO);
    ::dup2(log_fd, STDOUT_FILENO);
    ::dup2(log_fd, STDERR_FILENO);
    ::close(null_fd);
    ::close(log_fd);
    d.design.owner = storage::owner_text(storage::local_process());  // the parent records the same owner for us
    started.in_child = true;
    return;
  }
  hand_over(d, storage::owner_text(storage::local_process(child)));
  started.design = d.design;
  started.child = child;
}

StoppedDesign LocalProcesses::stop(Home&, const storage::Project&, const storage::Design& design) {
  const auto parsed = storage::parse_owner(design.owner);
  const auto* owner = parsed ? std::get_if<storage::LocalProcess>(&*parsed) : nullptr;
  if (!owner)
    throw Conflict("design " + std::to_string(design.id) + " runs in a web server (run-exp); stop it from the web app");
  if (!storage::runs_here(*owner))
    throw Conflict("design " + std::to_string(design.id) + " runs on another machine (" + design.owner + ")");
  ::kill(static_cast<pid_t>(owner->pid), SIGTERM);
  // Its lease dies with the process: wait for that, so that status right after agrees.
  for (int i = 0; i < 200 && storage::owner_alive(design.owner, design.heartbeat_at, design.heartbeat_at, design.pid); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  return {design, "stopped process " + std::to_string(owner->pid)};
}

}  // namespace sd::app
