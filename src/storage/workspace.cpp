#include "storage/workspace.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>

#include "core/home.hpp"
#include "storage/clock.hpp"
#include "storage/errors.hpp"
#include "storage/schema.hpp"
#include "storage/session_file.hpp"
#include "storage/sessions.hpp"

namespace sd::storage {

namespace {
// The home holds password hashes and session tokens: private to its owner when we create it.
void create_private_directory(const std::filesystem::path& folder) {
  if (std::filesystem::exists(folder)) return;
  std::filesystem::create_directories(folder);
  std::filesystem::permissions(folder, std::filesystem::perms::owner_all, std::filesystem::perm_options::replace);
}

// Create the database file ourselves so that it is 0600 from its first byte (SQLite would
// use the umask); SQLite gives its -wal and -shm files the same mode. An empty file is a
// valid empty database.
void create_private_file(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
  if (fd < 0) {
    if (errno == EEXIST) return;  // another process was first
    throw std::system_error(errno, std::generic_category(), "cannot create " + path.string());
  }
  ::close(fd);
}

const char* const kSignInHint = "sign in with: swarmdesign sign-in USER";
}  // namespace

Workspace::Workspace() : Workspace(sd::swarmdesign_home()) {}

Workspace::Workspace(std::filesystem::path home) : home_(std::move(home)) {
  create_private_directory(home_);
  const auto path = home_ / "swarmdesign.db";
  create_private_file(path);
  database_ = std::make_unique<Database>(path);
  migrate(*database_);
}

std::filesystem::path Workspace::projects_folder(const User& user) {
  return std::filesystem::path("users") / user.name / "projects";
}

std::optional<User> Workspace::signed_in_user() {
  try {
    return require_signed_in_user();
  } catch (const AccessDenied&) {
    return std::nullopt;
  }
}

User Workspace::require_signed_in_user() {
  const auto token = read_session_file(session_file());
  if (!token) throw AccessDenied(std::string("not signed in; ") + kSignInHint);
  const auto session = find_session(*database_, *token);
  if (!session) throw AccessDenied(std::string("not signed in (the session has ended); ") + kSignInHint);
  if (session->expired(unix_now()))
    throw AccessDenied("the session of " + session->user.name + " has expired; " + kSignInHint);
  return session->user;
}

}  // namespace sd::storage
