#include "app/background_designs.hpp"

#include <iostream>

#include "app/errors.hpp"
#include "storage/lease.hpp"

namespace sd::app {

StartedDesign BackgroundDesigns::start(Home& home, const storage::User& user, const DesignLaunch& launch) {
  std::lock_guard lock(start_mutex_);
  const BackgroundJobs::Counts running = jobs_.running(user.id);
  if (running.mine >= kPerUser)
    throw Conflict("you have " + std::to_string(running.mine) + " designs running on this server, the most one user may: "
                   "stop one, or run more with the CLI (run-design) or on a cluster");
  if (running.all >= kPerServer)
    throw Conflict("this server runs " + std::to_string(running.all) + " designs already, the most it takes: try again "
                   "when one has finished");
  ProjectDesignRequest request = launch.design;
  request.owner = storage::owner_text(storage::server_thread(job_ + "-" + std::to_string(next_job_++)));
  request.files = FileScope::own_projects(home, user);  // a server's user names only their own files
  // Refuses a project whose design still runs (here or in another process) before any change.
  auto design = std::make_shared<ProjectDesign>(start_project_design(home, user, request));
  jobs_.launch(design->design.id, user.id, design->project.id, [design](const CancelToken& cancel) {
    try {
      run_project_design(*design, {.threads = 0, .evaluator = nullptr, .observer = nullptr, .cancel = &cancel});
    } catch (const std::exception& e) {  // recorded as failed by the job; the server goes on
      std::cerr << "design " << design->design.id << " failed: " << e.what() << "\n";
    }
  });
  return {design->project, design->design, design->resumed, design->abandoned, design->prepared.choice.notes,
          std::nullopt, false, 0, std::nullopt, "this server"};
}

StoppedDesign BackgroundDesigns::stop(Home&, const storage::Project&, const storage::Design& design) {
  if (!jobs_.cancel(design.id))
    throw Conflict("design " + std::to_string(design.id) + " runs in another process (pid " + std::to_string(design.pid) +
                   "): stop it there");
  return {design, "asked its thread to stop after the current race step"};
}

bool BackgroundDesigns::running_here(std::int64_t project_id) const { return jobs_.runs_in_group(project_id); }

}  // namespace sd::app
