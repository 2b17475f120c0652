#pragma once
// The SwarmDesign home opened for one request: the accounts and projects database (migrated
// to the latest schema) and the users' folders, under core/home.hpp's one rule. Every account,
// project and design job of the application layer takes a Home.
#include <filesystem>

#include "storage/workspace.hpp"

namespace sd::app {

class Home {
 public:
  Home() = default;  // swarmdesign_home()
  explicit Home(std::filesystem::path folder) : workspace_(std::move(folder)) {}

  storage::Workspace& workspace() { return workspace_; }
  const std::filesystem::path& folder() const { return workspace_.home(); }

 private:
  storage::Workspace workspace_;
};

}  // namespace sd::app
