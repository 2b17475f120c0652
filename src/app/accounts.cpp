#include "app/accounts.hpp"

#include "app/errors.hpp"
#include "storage/clock.hpp"
#include "storage/passwords.hpp"
#include "storage/session_file.hpp"
#include "storage/sessions.hpp"
#include "storage/sodium.hpp"
#include "storage/validation.hpp"

namespace sd::app {

namespace {
void require_valid_user_name(const std::string& name) {
  if (auto problem = storage::user_name_problem(name); !problem.empty()) throw InvalidRequest(problem);
}

/// The one sign-in check of every front end: a locked name is refused before its password is
/// even looked at; a failure is counted, a success clears the count.
storage::User authenticate_counted(Home& home, const std::string& name, const std::string& password,
                                   const storage::SignInPolicy& policy) {
  require_valid_user_name(name);
  storage::Database& db = home.workspace().database();
  storage::SignInAttempts attempts(db, policy);
  if (const std::int64_t wait = attempts.locked_for(name, storage::unix_now()); wait > 0)
    throw storage::TooManyAttempts("too many failed sign-ins for '" + name + "': try again in " +
                                       std::to_string(wait) + " s",
                                   wait);
  try {
    storage::User user = storage::authenticate(db, name, password);
    attempts.succeeded(name);
    return user;
  } catch (const AccessDenied&) {
    attempts.failed(name, storage::unix_now());
    throw;
  }
}
}  // namespace

void check_new_user_name(Home& home, const std::string& name) {
  require_valid_user_name(name);
  if (storage::user_exists(home.workspace().database(), name))
    throw Conflict("user name '" + name + "' is already taken; choose another");
}

storage::User sign_up(Home& home, const std::string& name, const std::string& password) {
  check_new_user_name(home, name);
  if (auto problem = storage::password_problem(password, name); !problem.empty()) throw InvalidRequest(problem);
  return storage::create_user(home.workspace().database(), name, password);
}

SignedIn sign_in_here(Home& home, const std::string& name, const std::string& password,
                      const storage::SignInPolicy& policy) {
  storage::Workspace& ws = home.workspace();
  const auto user = authenticate_counted(home, name, password, policy);
  // The session this replaces, if any, is ended once the new one is in place.
  std::optional<std::string> previous;
  try {
    previous = storage::read_session_file(ws.session_file());
  } catch (const AccessDenied&) {
    // An unreadable or unsafe old file is simply replaced.
  }
  const auto session = storage::start_session(ws.database(), user);
  try {
    storage::write_session_file(ws.session_file(), session.token);
  } catch (...) {
    storage::end_session(ws.database(), session.token);
    throw;
  }
  if (previous) storage::end_session(ws.database(), *previous);
  return {user, session.expires_at};
}

SignedOut sign_out_here(Home& home) {
  storage::Workspace& ws = home.workspace();
  SignedOut out;
  std::optional<std::string> token;
  try {
    token = storage::read_session_file(ws.session_file());
  } catch (const AccessDenied&) {
    // Signing out must work even with a damaged or unsafe session file: just remove it.
    storage::remove_session_file(ws.session_file());
    out.removed_damaged_file = true;
    return out;
  }
  if (!token) return out;
  out.was_signed_in = true;
  if (const auto session = storage::find_session(ws.database(), *token)) out.user = session->user.name;
  storage::end_session(ws.database(), *token);
  storage::remove_session_file(ws.session_file());
  return out;
}

storage::User signed_in_user(Home& home) { return home.workspace().require_signed_in_user(); }

UserList list_users(Home& home) {
  UserList list;
  if (const auto me = home.workspace().signed_in_user()) list.me = me->id;
  list.users = storage::list_users(home.workspace().database());
  return list;
}

std::string open_session(Home& home, const std::string& name, const std::string& password,
                         const storage::SignInPolicy& policy) {
  const auto user = authenticate_counted(home, name, password, policy);
  return storage::start_session(home.workspace().database(), user).token;
}

storage::User user_of_session(Home& home, const std::string& token) {
  const auto session = storage::find_session(home.workspace().database(), token);
  if (!session || session->expired(storage::unix_now()))
    throw AccessDenied("not signed in (the session is unknown or has expired)");
  return session->user;
}

void close_session(Home& home, const std::string& token) { storage::end_session(home.workspace().database(), token); }

void ready_sign_ins() {
  storage::ensure_sodium();
  storage::dummy_password_hash();
}

}  // namespace sd::app
