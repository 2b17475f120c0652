#pragma once
// The design processes of one project: the rows `run-design` writes and `status` reads.
// Progress inside a race (iterations, experiments, elites, the log) is not kept here but in
// the design's own folder, where the optimiser keeps its race state in its own SQLite file.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "storage/lease.hpp"
#include "storage/projects.hpp"
#include "storage/workspace.hpp"

namespace sd::storage {

enum class DesignState { running, finished, failed, interrupted };

std::string to_string(DesignState state);
/// Reads back what to_string wrote.
DesignState design_state_from(const std::string& text);

/// What run-design was asked for; mission and budget are copied from the project.
struct DesignRequest {
  std::string architectures;  // e.g. "fsm,bt"
  std::string flavours;       // e.g. "chocolate,maple"
  std::uint64_t seed = 0;
  std::string owner;          // the job that runs the design: Owner::text() (storage/lease.hpp)
  std::string method = "automode";  // design/methods.hpp
};

struct Design {
  std::int64_t id = 0;
  std::string architectures, flavours, mission;
  std::string method = "automode";  // the optimiser that races it (design/methods.hpp)
  std::int64_t budget = 0;
  std::uint64_t seed = 0;
  DesignState state = DesignState::running;
  std::string owner;             // Owner::text() of the job that runs or ran it
  int pid = 0;                   // the owner's process (for people)
  std::int64_t heartbeat_at = 0; // the owner's last renewal of its lease
  std::filesystem::path folder;  // absolute; holds the race data
  std::optional<std::string> best_config;
  std::optional<double> best_score;
  std::int64_t created_at = 0, updated_at = 0;
  std::optional<std::int64_t> finished_at;
};

class Designs {
 public:
  /// The designs of a project obtained through Projects (so already owned by the user).
  Designs(Workspace& workspace, Project project);

  /// Records a running design and creates its folder <project>/designs/<id>. Refuses a
  /// project without mission or budget, and a
  /// second running design (Conflict); a "running" design whose owner is gone is first
  /// marked interrupted.
  Design start(const DesignRequest& request);
  /// Marks an interrupted (or failed) design running again under a new owner.
  Design resume(std::int64_t design_id, const std::string& owner);
  /// Hands a running design to another owner (a detached design goes on in a child).
  void set_owner(std::int64_t design_id, const std::string& owner);
  /// Renews the owner's lease; false when the design is no longer this owner's to run.
  bool heartbeat(std::int64_t design_id, const std::string& owner);
  /// The owner stops a running design that it can resume later: it becomes interrupted.
  /// Conflict when the owner does not hold it (storage/lease.hpp).
  void release(std::int64_t design_id, const std::string& owner);
  void finish(std::int64_t design_id, const std::string& best_config, double best_score);
  void mark_failed(std::int64_t design_id);
  /// Gives up an interrupted design (it becomes failed; its folder stays), so that a new one
  /// can start: for a design that cannot be resumed any more.
  void abandon(std::int64_t design_id);
  /// Deletes a design that does not run (its row, its cluster job's row and its folder);
  /// Conflict while it runs, NotFound for another project's design.
  void remove(std::int64_t design_id);

  /// The current or last design, for `status`; running designs whose owner is gone are
  /// reported as interrupted.
  std::optional<Design> latest();
  /// One design of the project as recorded now; NotFound otherwise.
  Design get(std::int64_t design_id);
  std::vector<Design> list();

 private:
  Lease lease();
  void set_state(std::int64_t design_id, DesignState state, std::string_view from_states);
  void fail(std::int64_t design_id, std::string_view from_states);

  Workspace& workspace_;
  Project project_;
};

}  // namespace sd::storage
