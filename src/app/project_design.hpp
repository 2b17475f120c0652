#pragma once
// Designs of a project: the jobs behind `run-design` and `test-design`, and behind a server's
// "start" button, whichever backend runs them (design_backend.hpp). A design in a project is a design job
// (design_job.hpp) whose row in the designs table is leased by the job that runs it
// (storage/lease.hpp): renewed while it runs, released when it is cancelled, finished or
// failed when it ends, and found interrupted when its owner dies.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "app/design_job.hpp"
#include "app/home.hpp"
#include "app/user_files.hpp"
#include "storage/cluster_jobs.hpp"
#include "storage/design_status.hpp"
#include "storage/designs.hpp"
#include "storage/errors.hpp"
#include "storage/projects.hpp"

namespace sd::app {

struct ProjectDesignRequest {
  design::DesignSpaceRequest space;
  bool space_given = false;           // flags were given (ignored when an interrupted design resumes)
  std::optional<std::uint64_t> seed;  // nullopt: a random seed
  bool fresh = false;                 // give up an interrupted design instead of resuming it
  std::string owner;                  // storage::Owner::text() of the job that will run it
  std::optional<std::string> project; // a project by name (a server); nullopt: the active one
  FileScope files = FileScope::local(); // where its mission file may be (a server: the user's projects)
  std::string pseudo_reality{};         // a robust design's specification (NewDesignSettings)
  std::string pseudo_reality_samples = std::string(kDefaultDesignSamples);
  const design::MethodInfo* method = &design::kAutoMoDe;  // the optimiser (NewDesignSettings)
};

struct ProjectDesign {
  std::filesystem::path home;         // the SwarmDesign home that records it
  storage::Project project;
  storage::Design design;             // as recorded: running, owned by the request's owner
  PreparedDesign prepared;
  bool resumed = false;
  std::optional<storage::Design> abandoned;  // an interrupted design given up by `fresh`
};

/// A design asked for again that would only repeat one that finished: the same mission (file
/// content included), budget, design space and the seed given explicitly. Run again after a
/// kill that came after the design had ended, the command finds its result, not a copy of it.
struct AlreadyFinished : storage::Conflict {
  AlreadyFinished(storage::Design finished, const std::string& project);
  storage::Design design;
};

/// Whether a start, given the project's latest design, resumes it rather than making another:
/// it was interrupted and no fresh design is asked (what start_project_design does, for the
/// quota to know beforehand that a resume counts no runs).
bool resumes(const std::optional<storage::Design>& latest, bool fresh);

/// Resumes the project's interrupted design (unless `fresh`), or records a new one with the
/// project's mission and budget. Everything that can be refused is checked before the designs
/// table changes. AlreadyFinished (unless `fresh`) when the new one would repeat the last.
ProjectDesign start_project_design(Home& home, const storage::User& user, const ProjectDesignRequest& request);

/// Runs it, renewing its lease, and records how it ended: finished (best configuration and
/// score), failed (an error, rethrown), or interrupted (cancelled: it resumes later).
DesignOutcome run_project_design(ProjectDesign& design, const DesignRunOptions& options);

/// Hands a running design to another owner (a detached child process takes it over): the
/// parent records the child as owner; the child sets design.owner to the same text itself.
void hand_over(ProjectDesign& design, const std::string& new_owner);

}  // namespace sd::app
