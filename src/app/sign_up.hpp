#pragma once
// Who may make an account on a server's page (issue #56): nobody (closed, the default: accounts
// are made at the server's terminal), whoever brings an administrator's invitation (invite),
// or anyone who reaches the page (open). `run-exp --sign-up`; the administrator makes, lists
// and revokes invitations from the CLI (`admin invite`) or the Admin tab.
#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "app/home.hpp"
#include "storage/accounts.hpp"
#include "storage/invitations.hpp"

namespace sd::app {

enum class SignUpPolicy { closed, invite, open };

/// nullopt for a word that is none of closed, invite, open.
std::optional<SignUpPolicy> parse_sign_up_policy(std::string_view text);
std::string_view sign_up_policy_name(SignUpPolicy policy);

/// A sign-up from a server's page under `policy`. AccessDenied when sign-up is closed, when the
/// home has no account yet (its administrator signs up at the terminal first: the first
/// account administers the home, and must not be whoever reaches the page first), or, by
/// invitation, for a code that is unknown, used, expired or revoked (one message for all,
/// checked before the name so that a stranger learns nothing of the accounts); then as
/// sign_up(). The invitation is used up in the same transaction as the account is made; the
/// new account is then signed in (a session token for the page's cookie).
struct SignedUp {
  storage::User user;
  std::string token;
};
SignedUp sign_up_on_server(Home& home, SignUpPolicy policy, const std::string& name, const std::string& password,
                           const std::string& invitation);

/// Administrators only (AccessDenied otherwise). `days` from 1 to 90 (InvalidRequest otherwise).
storage::NewInvitation invite(Home& home, const storage::User& admin, int days);
std::vector<storage::InvitationRow> invitations(Home& home, const storage::User& admin);
void revoke_invitation(Home& home, const storage::User& admin, std::int64_t id);

/// {"id","code","expires_at"}: the code is in this document only.
nlohmann::json new_invitation_document(const storage::NewInvitation& invitation);
/// [{"id","created_by","created_at","expires_at","used_by","used_at","state"}], state one of
/// open, used, expired.
nlohmann::json invitations_document(const std::vector<storage::InvitationRow>& rows);

}  // namespace sd::app
