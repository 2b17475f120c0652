#pragma once
// Invitations (issue #56): on a server whose sign-up is by invitation, an administrator makes a
// one-time code and hands it over; whoever brings it signs up once, before it expires. Only a
// hash of the code is stored (a copy of the database lets nobody in).
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "storage/accounts.hpp"
#include "storage/sqlite.hpp"

namespace sd::storage {

/// One message for a code that is unknown, used, expired or revoked.
inline constexpr const char* kInvalidInvitation = "this invitation is not valid (used, expired or revoked): ask for another";

struct NewInvitation {
  std::int64_t id = 0;
  std::string code;  // shown once
  std::int64_t expires_at = 0;
};

struct InvitationRow {
  std::int64_t id = 0;
  std::optional<std::string> created_by, used_by;  // account names (nullopt: none, or deleted)
  std::int64_t created_at = 0, expires_at = 0;
  std::optional<std::int64_t> used_at;
  std::optional<std::int64_t> revoked_at;
};

NewInvitation create_invitation(Database& db, std::int64_t admin_id, std::int64_t lifetime_seconds);
std::vector<InvitationRow> invitation_rows(Database& db);
/// Marks it revoked (it stays listed); NotFound for an unknown id or one already used or revoked.
void revoke_invitation(Database& db, std::int64_t id);
/// Whether the code opens a sign-up now (unused, unrevoked, unexpired); reads only.
bool invitation_open(Database& db, std::string_view code, std::int64_t now);
/// Marks the code used by `user`, inside the caller's transaction (create_user's `also`);
/// AccessDenied when it no longer opens a sign-up (used meanwhile, expired).
void use_invitation(Database& db, std::string_view code, const User& user, std::int64_t now);

}  // namespace sd::storage
