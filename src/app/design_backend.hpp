#pragma once
// Where a project's design runs, behind one interface: a local process (a CLI in the
// foreground, or its detached child), a thread of a long-lived server (the web app's Start),
// or a Slurm job (a cluster project). Each backend starts, stops and follows its designs;
// front ends ask `start_design`, `stop_design` (design_backends.hpp) and `design_status`
// (project_design.hpp) and never decide where a design runs nor read who owns it: that is
// chosen once, in design_backends.cpp, from the project (where new designs go) and from the
// design's typed owner (who can stop it).
//
// The backends: LocalProcesses (local_processes.hpp), BackgroundDesigns (background_designs.hpp,
// a server's threads), SlurmJobs (cluster_designs.hpp). To add one: a class implementing
// DesignBackend in a file of its own, an owner type for the rows it leases (storage/lease.hpp,
// with its text), and a line in `backend_for` and `stopper_of` (design_backends.cpp).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/home.hpp"
#include "app/project_design.hpp"
#include "app/slurm_jobs.hpp"
#include "storage/cluster_jobs.hpp"
#include "storage/design_status.hpp"
#include "storage/designs.hpp"

namespace sd::app {

/// What a front end asks when it starts (or resumes) a project's design.
struct DesignLaunch {
  ProjectDesignRequest design;
  ClusterJobRequest slurm;  // a cluster project's sbatch settings; refused for a local project
  bool detach = false;      // a local process: go on in a child that survives the terminal
  int mpi_ranks = 1;        // the ranks this process runs under (a child would leave them behind)
};

/// A design started or resumed, and where it now runs.
struct StartedDesign {
  storage::Project project;
  storage::Design design;
  bool resumed = false;                      // an interrupted design goes on
  std::optional<storage::Design> abandoned;  // an interrupted design given up by `fresh`
  std::vector<std::string> notes;            // about the design space chosen
  /// The design for this process to run now (a CLI in the foreground, or the detached child
  /// it became); nullopt when it runs elsewhere.
  std::optional<ProjectDesign> run_here;
  bool in_child = false;                     // this process is the detached child
  std::int64_t child = 0;                    // the parent: the child's pid
  std::optional<storage::ClusterJob> job;    // a Slurm job's
  std::string where;                         // a Slurm job's cluster: "this machine" or "user@host (ssh)"
};

struct StoppedDesign {
  storage::Design design;  // as recorded after the stop (a thread asked to stop still runs its step)
  std::string how;         // one line: what was done
};

class DesignBackend {
 public:
  virtual ~DesignBackend() = default;
  /// Records the design (new or resumed) and starts it where this backend runs designs.
  virtual StartedDesign start(Home& home, const storage::User& user, const DesignLaunch& launch) = 0;
  /// Stops the project's running design (it becomes interrupted, resumable). Conflict when
  /// this backend cannot reach its owner.
  virtual StoppedDesign stop(Home& home, const storage::Project& project, const storage::Design& design) = 0;
  /// Brings a running design up to date with where it runs; the progress read there, or
  /// nullopt when its folder here holds it (design_status then reads it).
  virtual std::optional<storage::DesignProgress> refresh(Home& home, const storage::Project& project,
                                                         storage::Design& design) = 0;
};

}  // namespace sd::app
