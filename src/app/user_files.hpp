#pragma once
// The one rule for the files a user names (a mission, a configuration file, a protocol, the
// files of their projects a server reads), for every front end and every job:
// - on one's own machine (the CLI) a user reads where they point, but only a regular file of
//   at most 1 MiB (core/bounded_file.hpp);
// - through a shared server a user reads only inside their own projects' folders: no other
//   user's file, no "..", no link that leads out. What may not be used is refused with the
//   same status and the same words whether it exists or not, and no refusal quotes a file.
#include <filesystem>
#include <optional>
#include <string>

#include "app/home.hpp"
#include "missions/mission.hpp"
#include "storage/accounts.hpp"

namespace sd::app {

class FileScope {
 public:
  /// The CLI on the user's own machine: any file the operating system lets them read.
  static FileScope local() { return FileScope(std::nullopt); }
  /// A user of a shared server: their own projects' folders, nothing else.
  static FileScope own_projects(const Home& home, const storage::User& user);

  bool is_local() const { return !root_; }
  /// Whether a (not yet resolved) path leads inside the scope.
  bool allows(const std::filesystem::path& path) const;
  /// The same rule for a reader below the application (a mission's module-set folder): asked
  /// about the real path of each file opened; empty (anything) for the CLI.
  PathRule path_rule() const;
  /// The whole text of a file the user named, `what` naming it in messages ("mission file").
  /// NotFound (one message for missing and forbidden) outside the scope; InvalidRequest for a
  /// special or oversized file; NotFound naming the error for a missing file on the CLI.
  std::string read(const std::string& path, const std::string& what) const;
  /// The folder `path`, made if missing, provided it lies inside the scope (a link planted in
  /// a project cannot send a write elsewhere); NotFound as read() otherwise.
  std::filesystem::path writable_folder(const std::filesystem::path& path, const std::string& what) const;

 private:
  explicit FileScope(std::optional<std::filesystem::path> root) : root_(std::move(root)) {}
  [[noreturn]] void refuse(const std::string& path, const std::string& what) const;

  std::optional<std::filesystem::path> root_;  // real path of the user's projects folder
};

/// A mission the user named: a catalogue name, or a mission file the scope lets them read.
/// InvalidRequest for an unknown name or a malformed file (naming the bad field), the scope's
/// refusals otherwise.
Mission load_requested_mission(const std::string& name_or_path, const FileScope& scope = FileScope::local());
/// The mission run with the Arlequin module set the user named (--arlequin-modules:
/// swarmdesign, demiurge or a folder the scope lets them read); `mission` itself if the name
/// is empty. InvalidRequest in one line for a bad set.
Mission with_requested_arlequin_modules(const Mission& mission, const std::string& name_or_folder,
                                        const FileScope& scope = FileScope::local());
/// The mission started from the tick-0 poses of the trace file the user named (evaluate
/// --start-from; the command line's only: a whole trace is larger than the web's 1 MiB inputs);
/// `mission` itself if the path is empty. InvalidRequest in one line for a bad trace.
Mission with_start_from(const Mission& mission, const std::string& path);

}  // namespace sd::app
