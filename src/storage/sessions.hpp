#pragma once
// Signed-in sessions. A session is a random 256-bit token: the database keeps only its
// BLAKE2b hash (a stolen database opens no session), the user keeps the token in a file
// only they can read (session_file.hpp). Sessions expire after kSessionLifetime.
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "storage/accounts.hpp"
#include "storage/sqlite.hpp"

namespace sd::storage {

constexpr std::chrono::seconds kSessionLifetime = std::chrono::hours(24 * 7);

struct NewSession {
  std::string token;  // hex; goes to the session file, never to the database
  std::int64_t expires_at = 0;
};

struct SessionRecord {
  User user;
  std::int64_t expires_at = 0;
  bool expired(std::int64_t now) const { return expires_at <= now; }
};

/// Opens a session for the user and drops every expired session on the way.
NewSession start_session(Database& db, const User& user);

/// The session a token belongs to, expired or not; nullopt for an unknown token.
std::optional<SessionRecord> find_session(Database& db, std::string_view token);

/// Ends the session (no-op for an unknown token).
void end_session(Database& db, std::string_view token);

/// Ends every session of the user but the one of `except_token` (none when nullopt).
void end_sessions_of(Database& db, std::int64_t user_id, std::optional<std::string_view> except_token = std::nullopt);

}  // namespace sd::storage
