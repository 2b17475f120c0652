#pragma once
// A lab's server administered (issue #56): an administrator lists the accounts with what each
// uses, disables and enables them, gives one a new one-time password, makes another an
// administrator, or deletes one with everything it owns; every user changes their own
// password. The CLI's `admin ...` and `change-password`, the web's /api/admin and /api/password.
#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "app/home.hpp"
#include "app/quotas.hpp"
#include "storage/account_admin.hpp"

namespace sd::app {

struct AccountUse {
  storage::AccountRow account;
  std::uint64_t disk_bytes = 0;  // everything under the account's folder (links not followed)
  int running_designs = 0, running_experiments = 0;
  QuotaUse quota;
};

/// AccessDenied unless `who` is an administrator.
void require_admin(Home& home, const storage::User& who);
bool is_admin(Home& home, const storage::User& who);

std::vector<AccountUse> account_uses(Home& home, const storage::User& admin);
/// Disabling ends the account's sessions; an administrator cannot disable themselves.
void set_account_disabled(Home& home, const storage::User& admin, const std::string& name, bool disabled);
/// A new random password for the account (every session of it ends), shown once to the
/// administrator to hand over; the user changes it with change-password.
std::string reset_account_password(Home& home, const storage::User& admin, const std::string& name);
/// The last administrator keeps the role.
void set_account_role(Home& home, const storage::User& admin, const std::string& name, storage::Role role);
/// The account, its projects, designs, experiments and files; `confirm` must repeat its name.
/// Conflict while one of its designs or experiments runs; never oneself.
void delete_account(Home& home, const storage::User& admin, const std::string& name, const std::string& confirm);

/// A user's own new password: the old one checked first (AccessDenied when wrong), every other
/// session of the account ended (the one of `keep_token` stays).
void change_password(Home& home, const storage::User& user, const std::string& old_password,
                     const std::string& new_password, std::optional<std::string> keep_token);

/// change_password for the user signed in on this machine, keeping this machine's session.
void change_password_here(Home& home, const std::string& old_password, const std::string& new_password);

nlohmann::json accounts_document(const std::vector<AccountUse>& accounts);

}  // namespace sd::app
