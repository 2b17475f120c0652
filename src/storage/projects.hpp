#pragma once
// A user's projects. Every query is scoped to the owner given at construction, so another
// user's project is indistinguishable from one that does not exist.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "storage/accounts.hpp"
#include "storage/workspace.hpp"

namespace sd::storage {

struct ClusterConnection {
  std::string host;
  std::string user;
  std::string workdir;  // job folders on the cluster ("": ~/swarmdesign)
  std::string binary;   // the swarmdesign program there ("": the one on its PATH)
  std::string workdir_or_default() const { return workdir.empty() ? "~/swarmdesign" : workdir; }
  std::string binary_or_default() const { return binary.empty() ? "swarmdesign" : binary; }
};

struct Project {
  std::int64_t id = 0;
  std::string name;
  std::filesystem::path folder;             // absolute
  std::optional<std::string> mission;       // catalogue name or mission file path
  std::optional<std::int64_t> budget;       // simulation runs
  std::optional<ClusterConnection> cluster; // nullopt: runs on this machine
  std::int64_t created_at = 0;
  bool active = false;                      // the owner's selected project
};

class Projects {
 public:
  Projects(Workspace& workspace, User owner);

  /// Records the project and creates its folder; Conflict if the owner has one so named.
  Project create(std::string_view name, const std::optional<ClusterConnection>& cluster);
  std::vector<Project> list();
  /// NotFound (same words for a foreign project) when the owner has no such project.
  Project get(std::string_view name);
  Project select(std::string_view name);
  /// Deletes the project: its rows (designs, experiments, their results) and its folder with
  /// everything in it. Conflict while one of its designs or experiments runs.
  void remove(std::string_view name);
  std::optional<Project> active();
  /// NotFound with a hint when no project is selected.
  Project require_active();

  Project set_budget(std::int64_t budget);
  Project set_mission(const std::string& mission);
  /// Where the active (cluster) project's jobs go and which program runs them; "" keeps one.
  Project set_cluster_paths(const std::string& workdir, const std::string& binary);

 private:
  std::optional<Project> query_one(std::string_view condition, std::string_view value);

  Workspace& workspace_;
  User owner_;
};

}  // namespace sd::storage
