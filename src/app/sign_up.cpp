#include "app/sign_up.hpp"

#include <nlohmann/json.hpp>

#include "app/account_admin.hpp"
#include "app/accounts.hpp"
#include "app/errors.hpp"
#include "storage/clock.hpp"
#include "storage/passwords.hpp"
#include "storage/sessions.hpp"

namespace sd::app {

namespace {

nlohmann::json optional_json(const auto& value) { return value ? nlohmann::json(*value) : nlohmann::json(); }

}  // namespace

std::optional<SignUpPolicy> parse_sign_up_policy(std::string_view text) {
  if (text == "closed") return SignUpPolicy::closed;
  if (text == "invite") return SignUpPolicy::invite;
  if (text == "open") return SignUpPolicy::open;
  return std::nullopt;
}

std::string_view sign_up_policy_name(SignUpPolicy policy) {
  switch (policy) {
    case SignUpPolicy::closed: return "closed";
    case SignUpPolicy::invite: return "invite";
    case SignUpPolicy::open: return "open";
  }
  return "closed";
}

SignedUp sign_up_on_server(Home& home, SignUpPolicy policy, const std::string& name, const std::string& password,
                           const std::string& invitation) {
  if (policy == SignUpPolicy::closed)
    throw AccessDenied("sign-up is closed on this server: ask its administrator for an account");
  storage::Database& db = home.workspace().database();
  if (storage::list_users(db).empty())
    throw AccessDenied("this server has no administrator yet: make the first account with `swarmdesign sign-up` on its machine");
  if (policy == SignUpPolicy::invite && !storage::invitation_open(db, invitation, storage::unix_now()))
    throw AccessDenied(storage::kInvalidInvitation);
  check_new_user_name(home, name);
  if (auto problem = storage::password_problem(password, name); !problem.empty()) throw InvalidRequest(problem);
  const storage::User user =
      policy == SignUpPolicy::open ? storage::create_user(db, name, password)
                                   : storage::create_user(db, name, password, [&](const storage::User& made) {
                                       storage::use_invitation(db, invitation, made, storage::unix_now());
                                     });
  return {user, storage::start_session(db, user).token};
}

storage::NewInvitation invite(Home& home, const storage::User& admin, int days) {
  require_admin(home, admin);
  if (days < 1 || days > 90) throw InvalidRequest("an invitation lasts 1 to 90 days, not " + std::to_string(days));
  return storage::create_invitation(home.workspace().database(), admin.id, std::int64_t{days} * 86400);
}

std::vector<storage::InvitationRow> invitations(Home& home, const storage::User& admin) {
  require_admin(home, admin);
  return storage::invitation_rows(home.workspace().database());
}

void revoke_invitation(Home& home, const storage::User& admin, std::int64_t id) {
  require_admin(home, admin);
  storage::revoke_invitation(home.workspace().database(), id);
}

nlohmann::json new_invitation_document(const storage::NewInvitation& invitation) {
  return {{"id", invitation.id}, {"code", invitation.code}, {"expires_at", invitation.expires_at}};
}

nlohmann::json invitations_document(const std::vector<storage::InvitationRow>& rows) {
  const std::int64_t now = storage::unix_now();
  nlohmann::json list = nlohmann::json::array();
  for (const storage::InvitationRow& r : rows)
    list.push_back({{"id", r.id},
                    {"created_by", optional_json(r.created_by)},
                    {"created_at", r.created_at},
                    {"expires_at", r.expires_at},
                    {"used_by", optional_json(r.used_by)},
                    {"used_at", optional_json(r.used_at)},
                    {"revoked_at", optional_json(r.revoked_at)},
                    {"state", r.used_at      ? "used"
                              : r.revoked_at ? "revoked"
                              : r.expires_at <= now ? "expired"
                                                    : "open"}});
  return list;
}

}  // namespace sd::app
