#pragma once
// Accounts and sessions as the application offers them. A terminal keeps its session token in
// the home's session file (sign_in_here); a web server keeps it in a cookie (open_session,
// user_of_session). Passwords are only ever stored as Argon2id hashes (storage/passwords).
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/home.hpp"
#include "storage/accounts.hpp"
#include "storage/sessions.hpp"
#include "storage/sign_in_attempts.hpp"

namespace sd::app {

/// InvalidRequest when the name breaks the rule; Conflict when it is taken (checked before a
/// password is asked for, so none is thrown away).
void check_new_user_name(Home& home, const std::string& name);
/// InvalidRequest for a malformed name or a password that breaks the rule.
storage::User sign_up(Home& home, const std::string& name, const std::string& password);

struct SignedIn {
  storage::User user;
  std::int64_t expires_at = 0;
};
/// Signs in on this machine: a new session whose token replaces the session file (the session
/// it replaces is ended). AccessDenied for a wrong name or password (the same words for both),
/// TooManyAttempts while the name is locked out after repeated failures (`policy`).
SignedIn sign_in_here(Home& home, const std::string& name, const std::string& password,
                      const storage::SignInPolicy& policy = {});

struct SignedOut {
  bool was_signed_in = false;
  bool removed_damaged_file = false;  // the session file could not be read; it is gone
  std::optional<std::string> user;
};
SignedOut sign_out_here(Home& home);

/// The user signed in on this machine; AccessDenied saying why not and how to sign in.
storage::User signed_in_user(Home& home);

struct UserList {
  std::vector<storage::User> users;
  std::optional<std::int64_t> me;  // id of the user signed in here
};
UserList list_users(Home& home);

/// For a server: a session for these credentials (token to keep in a cookie), with
/// sign_in_here's errors and lock-out; and the user of a token (AccessDenied when unknown or
/// expired).
std::string open_session(Home& home, const std::string& name, const std::string& password,
                         const storage::SignInPolicy& policy = {});
storage::User user_of_session(Home& home, const std::string& token);
void close_session(Home& home, const std::string& token);
/// How long a session lasts (a server's cookie lasts as long).
inline constexpr std::chrono::seconds kSessionLifetime = storage::kSessionLifetime;

/// A server's start: libsodium ready for its keys and tokens, and the dummy password hash made
/// (a sign-in of an unknown name checks against it, so it costs what a known name's does).
void ready_sign_ins();

}  // namespace sd::app
