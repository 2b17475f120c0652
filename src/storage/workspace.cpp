#include "storage/workspace.hpp"

#include "core/home.hpp"
#include "core/private_files.hpp"
#include "storage/clock.hpp"
#include "storage/errors.hpp"
#include "storage/schema.hpp"
#include "storage/session_file.hpp"
#include "storage/sessions.hpp"

namespace sd::storage {

namespace {
const char* const kSignInHint = "sign in with: swarmdesign sign-in USER";
}  // namespace

Workspace::Workspace() : Workspace(sd::swarmdesign_home()) {}

Workspace::Workspace(std::filesystem::path home) : home_(std::move(home)) {
  create_private_folders(home_);
  database_ = std::make_unique<Database>(home_ / "swarmdesign.db");  // created 0600
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
