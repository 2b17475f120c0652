#pragma once
// The designs a process runs itself (the CLI's run-design): one at a time, in the foreground
// or in a detached child that survives the terminal; leased by a storage::LocalProcess and
// stopped with SIGTERM from another process of this machine (stop-design, the web app).
#include "app/design_backend.hpp"

namespace sd::app {

class LocalProcesses final : public DesignBackend {
 public:
  /// The design is for this process to run (StartedDesign::run_here).
  StartedDesign start(Home& home, const storage::User& user, const DesignLaunch& launch) override;
  /// SIGTERM to a CLI process of this machine, waiting until its lease is gone. Conflict for a
  /// server's thread (its server stops it) or a process on another machine.
  StoppedDesign stop(Home& home, const storage::Project& project, const storage::Design& design) override;
  std::optional<storage::DesignProgress> refresh(Home&, const storage::Project&, storage::Design&) override {
    return std::nullopt;
  }

  /// Goes on in a child process with its own session, no terminal, output in DIR/design.log;
  /// parent and child both hand the lease to the child. Returns in both: `in_child` in the
  /// child (which then runs it), `child` in the parent. No database connection may be open
  /// (SQLite's rule for fork).
  static void detach(StartedDesign& started);
};

}  // namespace sd::app
