#pragma once
// A SwarmDesign home opened for one command: the database (migrated to the latest schema),
// the session file, and the users' folders. Every account and project command starts here.
#include <filesystem>
#include <memory>
#include <optional>

#include "storage/accounts.hpp"
#include "storage/sqlite.hpp"

namespace sd::storage {

class Workspace {
 public:
  /// The home of swarmdesign_home().
  Workspace();
  /// Creates the home (mode 0700) and the database (mode 0600) when missing.
  explicit Workspace(std::filesystem::path home);

  Database& database() { return *database_; }
  const std::filesystem::path& home() const { return home_; }
  std::filesystem::path session_file() const { return home_ / "session"; }

  /// A path stored relative to the home, made absolute.
  std::filesystem::path resolve(const std::filesystem::path& stored) const { return home_ / stored; }
  /// Where a user's projects live, relative to the home.
  static std::filesystem::path projects_folder(const User& user);

  /// The signed-in user, or nullopt (also for an expired or unreadable session).
  std::optional<User> signed_in_user();
  /// The signed-in user; AccessDenied saying why not and how to sign in.
  User require_signed_in_user();

 private:
  std::filesystem::path home_;
  std::unique_ptr<Database> database_;
};

}  // namespace sd::storage
